#include <string_view>

#include "fuzz_targets.h"

namespace rc::fuzz {

std::vector<std::pair<std::string, std::string>> split_files(const uint8_t* data, size_t size,
                                                             const std::string& first_name) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    constexpr std::string_view kMarker = "#@file ";
    std::vector<std::pair<std::string, std::string>> files;
    std::string name = first_name;
    size_t start = 0;
    for (;;) {
        size_t marker = text.find(kMarker, start);
        while (marker != std::string_view::npos && marker != 0 && text[marker - 1] != '\n') {
            marker = text.find(kMarker, marker + 1);
        }
        const size_t end = marker == std::string_view::npos ? text.size() : marker;
        files.emplace_back(name, std::string(text.substr(start, end - start)));
        if (marker == std::string_view::npos) {
            return files;
        }
        const size_t line_end = text.find('\n', marker);
        const size_t name_end = line_end == std::string_view::npos ? text.size() : line_end;
        name =
            std::string(text.substr(marker + kMarker.size(), name_end - marker - kMarker.size()));
        start = line_end == std::string_view::npos ? text.size() : line_end + 1;
    }
}

}  // namespace rc::fuzz
