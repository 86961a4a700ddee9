#include "util/file_io.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "util/error.h"

namespace rc {

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw Error(path.string() + ": cannot open file: " + std::strerror(errno));
    }
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad()) {
        throw Error(path.string() + ": read error");
    }
    return bytes.str();
}

std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    // Keeps the extension, which some writers use to pick the file variant.
    std::filesystem::path temporary = path;
    temporary.replace_filename(path.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                               std::to_string(counter++) + path.extension().string());
    return temporary;
}

void replace_file_atomically(const std::filesystem::path& path,
                             const std::function<void(const std::filesystem::path&)>& write) {
    const std::filesystem::path temporary = temporary_sibling(path);
    try {
        write(temporary);
        std::error_code error;
        std::filesystem::rename(temporary, path, error);
        if (error) {
            throw Error(path.string() + ": cannot write file: " + error.message());
        }
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
    replace_file_atomically(path, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) {
            throw Error(path.string() + ": cannot write file: " + std::strerror(errno));
        }
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out) {
            throw Error(path.string() + ": write error");
        }
    });
}

void check_writable_parent(const std::filesystem::path& file, const std::string& option) {
    const std::filesystem::path dir = file.parent_path().empty() ? "." : file.parent_path();
    if (!std::filesystem::is_directory(dir) || ::access(dir.c_str(), W_OK) != 0) {
        throw Error(option + " " + file.string() + ": directory '" + dir.string() +
                        "' does not exist or is not writable",
                    kExitUsage);
    }
}

}  // namespace rc
