// Where a scene's files come from: the file system, or memory (the fuzz targets read a scene and
// its meshes without touching the disk). Every read is of a regular file within a size limit
// (/dev/zero as a mesh or an MTL library is refused before any allocation).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace rc {

// The size limits of a scene's files (docs/scene-format.md).
inline constexpr uint64_t kMaxSceneFileBytes = uint64_t{64} << 20;
inline constexpr uint64_t kMaxMeshFileBytes = uint64_t{2} << 30;
inline constexpr uint64_t kMaxMaterialFileBytes = uint64_t{64} << 20;
inline constexpr uint64_t kMaxTextureFileBytes = uint64_t{1} << 30;
// The longest string a scene file's value may hold (names, types, file paths).
inline constexpr size_t kMaxSceneStringBytes = 4096;

class SceneFiles {
   public:
    virtual ~SceneFiles() = default;
    // Whether something (a file, a directory, a device) exists at `path`.
    virtual bool exists(const std::filesystem::path& path) const = 0;
    // Its bytes; Error naming the file (and `what` it is) when it is missing, not a regular file
    // or longer than `max_bytes`.
    virtual std::string read(const std::filesystem::path& path, uint64_t max_bytes,
                             const std::string& what) const = 0;
};

// The file system.
const SceneFiles& disk_files();

// Files held in memory, by their lexically normal path.
class MemoryFiles : public SceneFiles {
   public:
    void add(const std::filesystem::path& path, std::string bytes);
    bool exists(const std::filesystem::path& path) const override;
    std::string read(const std::filesystem::path& path, uint64_t max_bytes,
                     const std::string& what) const override;

   private:
    std::map<std::string, std::string> files_;
};

}  // namespace rc
