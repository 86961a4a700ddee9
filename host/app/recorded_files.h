// The files a scene loader read (the scene, its meshes, material libraries, textures, glTF
// buffers, pbrt includes), recorded so that no output of the run is one of them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/scene_files.h"
#include "util/output_identity.h"

namespace rc {

// A farmhash fingerprint of `bytes` as 16 hex digits: the same on any machine.
std::string bytes_digest(std::string_view bytes);

class RecordedFiles : public SceneFiles {
   public:
    explicit RecordedFiles(const SceneFiles& files = disk_files()) : files_(files) {}

    bool exists(const std::filesystem::path& path) const override { return files_.exists(path); }

    std::string read(const std::filesystem::path& path, uint64_t max_bytes,
                     const std::string& what) const override {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            read_.emplace_back(what, path);
        }
        std::string bytes = files_.read(path, max_bytes, what);
        const uint64_t fingerprint = bytes_fingerprint(bytes);
        const std::lock_guard<std::mutex> lock(mutex_);
        fingerprints_.emplace_back(path, fingerprint);
        return bytes;
    }

    // A fingerprint of every file read, each file's bytes bound to its role: its path relative to
    // the folder of the first file read (the scene file). The same scene, meshes and textures at
    // the same places under the scene's folder give the same 16 hex digits on any machine,
    // wherever that folder is and whatever order the files were read in; two files' contents
    // swapped give another.
    std::string content_digest() const;

    // Every file read, as the loader named it.
    std::vector<std::filesystem::path> paths() const {
        const std::lock_guard<std::mutex> lock(mutex_);
        std::vector<std::filesystem::path> paths;
        for (const auto& entry : read_) {
            paths.push_back(entry.second);
        }
        return paths;
    }

    // Every file read, each an input of `run` named by what it is ("mesh file").
    void add_inputs_to(RunFiles& run) const {
        const std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& [what, path] : read_) {
            run.input(what, path);
        }
    }

   private:
    const SceneFiles& files_;
    mutable std::mutex mutex_;
    mutable std::vector<std::pair<std::string, std::filesystem::path>> read_;
    mutable std::vector<std::pair<std::filesystem::path, uint64_t>> fingerprints_;

    static uint64_t bytes_fingerprint(const std::string& bytes);
};

}  // namespace rc
