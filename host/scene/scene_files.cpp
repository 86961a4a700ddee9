#include "scene/scene_files.h"

#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

class DiskFiles : public SceneFiles {
   public:
    bool exists(const std::filesystem::path& path) const override {
        std::error_code error;
        return std::filesystem::exists(path, error);
    }
    std::string read(const std::filesystem::path& path, uint64_t max_bytes,
                     const std::string& what) const override {
        return read_file(path, max_bytes, what);
    }
};

std::string key_of(const std::filesystem::path& path) { return path.lexically_normal().string(); }

}  // namespace

const SceneFiles& disk_files() {
    static const DiskFiles files;
    return files;
}

void MemoryFiles::add(const std::filesystem::path& path, std::string bytes) {
    files_[key_of(path)] = std::move(bytes);
}

bool MemoryFiles::exists(const std::filesystem::path& path) const {
    return files_.count(key_of(path)) != 0;
}

std::string MemoryFiles::read(const std::filesystem::path& path, uint64_t max_bytes,
                              const std::string& what) const {
    const auto found = files_.find(key_of(path));
    if (found == files_.end()) {
        throw Error(path.string() + " (" + what + "): cannot open file: no such file");
    }
    if (found->second.size() > max_bytes) {
        throw Error(path.string() + " (" + what + "): " + std::to_string(found->second.size()) +
                    " bytes, more than the limit of " + std::to_string(max_bytes));
    }
    return found->second;
}

}  // namespace rc
