#include "device/kernel_sources.h"

#include <algorithm>
#include <regex>
#include <sstream>

#include "device/embedded_sources.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

const char* find_embedded(const std::string& path) {
    for (size_t i = 0; i < kEmbeddedSourceCount; ++i) {
        if (path == kEmbeddedSources[i].path) {
            return kEmbeddedSources[i].text;
        }
    }
    return nullptr;
}

std::string normalized(const std::filesystem::path& path) {
    return path.lexically_normal().generic_string();
}

}  // namespace

KernelSources::KernelSources(std::filesystem::path override_dir)
    : override_dir_(std::move(override_dir)) {
    if (!override_dir_.empty() && !std::filesystem::is_directory(override_dir_)) {
        throw Error("kernel override directory '" + override_dir_.string() + "' is not a directory",
                    kExitUsage);
    }
}

bool KernelSources::exists(const std::string& path) const {
    if (override_dir_.empty()) {
        return find_embedded(path) != nullptr;
    }
    return std::filesystem::is_regular_file(override_dir_ / path);
}

std::string KernelSources::read(const std::string& path) const {
    if (!override_dir_.empty()) {
        return read_file(override_dir_ / path);
    }
    if (const char* text = find_embedded(path)) {
        return text;
    }
    throw Error("kernel source '" + path + "' is not embedded in this executable");
}

std::string KernelSources::expand(const std::string& entry) const {
    std::vector<std::string> included;
    std::string out;
    expand_into(normalized(entry), included, out);
    return out;
}

void KernelSources::expand_into(const std::string& path, std::vector<std::string>& included,
                                std::string& out) const {
    if (std::find(included.begin(), included.end(), path) != included.end()) {
        return;  // every kernel file is included once
    }
    included.push_back(path);
    static const std::regex include_quoted(R"(^\s*#\s*include\s*"([^"]+)\".*$)");
    static const std::regex pragma_once(R"(^\s*#\s*pragma\s+once\b.*$)");

    std::istringstream lines(read(path));
    out += "#line 1 \"" + path + "\"\n";
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        std::smatch match;
        if (std::regex_match(line, match, include_quoted)) {
            const std::string name = match[1].str();
            const std::string beside = normalized(std::filesystem::path(path).parent_path() / name);
            const std::string from_root = normalized(name);
            std::string target;
            if (exists(beside)) {
                target = beside;
            } else if (exists(from_root)) {
                target = from_root;
            } else {
                throw Error("kernel source " + path + ":" + std::to_string(number) +
                            ": included file '" + name + "' not found");
            }
            expand_into(target, included, out);
            out += "#line " + std::to_string(number + 1) + " \"" + path + "\"\n";
        } else if (std::regex_match(line, pragma_once)) {
            out += "\n";
        } else {
            out += line;
            out += "\n";
        }
    }
}

}  // namespace rc
