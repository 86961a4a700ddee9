// A built OpenCL program: expanded source, binary cache, build log on failure.
#pragma once

#include <string>

#include "device/binary_cache.h"
#include "device/kernel.h"
#include "device/kernel_sources.h"

struct _cl_program;
struct _cl_context;

namespace rc {

struct DeviceInfo;

// A program to build: its entry (relative to kernels/) and -D options, as Context::program takes
// them.
struct ProgramRequest {
    std::string entry;
    std::string options;
};

// How a program came to be: compiled from source, or loaded from the binary cache (and whether
// a corrupt cache entry was met and replaced on the way).
struct ProgramBuildReport {
    std::string entry;
    std::string options;  // its -D options (the BVH layout's left out)
    double seconds = 0.0;
    bool from_cache = false;
    bool replaced_corrupt_entry = false;
};

class Program {
   public:
    // Builds `entry` (a path relative to kernels/) with `context_defines` (what every program of
    // the Context gets) and `options` (-D definitions) for the device. Uses the binary cache when
    // it holds a valid entry; otherwise compiles and stores. A failed compilation throws Error with
    // the full build log. When `dump_dir` is not empty the expanded source is written there.
    Program(_cl_context* context, const DeviceInfo& device, const KernelSources& sources,
            const BinaryCache& cache, const std::string& entry, const std::string& context_defines,
            const std::string& options, const std::filesystem::path& dump_dir = {});
    ~Program();
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    Kernel kernel(const std::string& name) const;
    const ProgramBuildReport& report() const { return report_; }

   private:
    _cl_program* handle_ = nullptr;
    std::string entry_;
    ProgramBuildReport report_;
};

}  // namespace rc
