// Kernel source files and their expansion into one translation unit: the host resolves every
// #include itself (so the binary-cache key sees header changes) and keeps #line markers.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rc {

class KernelSources {
   public:
    // Sources embedded in the executable, or, with a non-empty override directory, the files
    // under that directory (all of them: nothing falls back to the embedded copies).
    explicit KernelSources(std::filesystem::path override_dir = {});

    // The text of one source file, by its path relative to the kernels directory.
    std::string read(const std::string& path) const;
    bool exists(const std::string& path) const;

    // `entry` with its #include "..." directives replaced by the files they name (resolved
    // relative to the including file, then to the kernels directory; each file once), with
    // #line markers so compiler messages name the original file and line. #include <...> lines
    // stay as they are: they belong to the host branch of kernels/shared/compat.h.
    std::string expand(const std::string& entry) const;

    const std::filesystem::path& override_dir() const { return override_dir_; }

   private:
    void expand_into(const std::string& path, std::vector<std::string>& included,
                     std::string& out) const;

    std::filesystem::path override_dir_;
};

}  // namespace rc
