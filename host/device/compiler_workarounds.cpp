#include "device/compiler_workarounds.h"

#include <cstdlib>

namespace rc {
namespace {

// $RADCACHE_NO_COMPILER_WORKAROUNDS=1: build without them (to check whether a new driver still
// needs one; the implementations test then shows it).
bool workarounds_disabled() {
    const char* value = std::getenv("RADCACHE_NO_COMPILER_WORKAROUNDS");
    return value != nullptr && std::string(value) == "1";
}

}  // namespace

std::vector<CompilerWorkaround> compiler_workarounds(const DeviceInfo& device) {
    std::vector<CompilerWorkaround> workarounds;
    // Intel's CPU runtime (2026.2, measured: docs/lab/devices.md, "Intel's CPU runtime"): it
    // vectorises a kernel across work items, and then (1) a device function it keeps out of line
    // (a masked vector variant, _ZGVeM16...) hands a float3 result to its caller one component
    // late, (x, y, z) arriving as (?, x, y), and (2) a work group smaller than its vector width
    // runs scalar code that rounds differently from the vector code (images that differ in their
    // last bits between --local-size 8 and 16). A kernel compiled for one work item at a time is
    // right on both counts, and no slower for radcache's divergent kernels.
    if (device.platform_name == "Intel(R) OpenCL" && device.is_cpu && !workarounds_disabled()) {
        workarounds.push_back(
            {"RC_SCALAR_WORK_ITEMS",
             "every kernel compiled one work item at a time (intel_vec_len_hint(1)): Intel's "
             "CPU compiler, vectorising across work items, returns a float3 from an out-of-line "
             "function one component late and rounds work groups under its vector width "
             "differently"});
    }
    return workarounds;
}

std::string compiler_workaround_options(const DeviceInfo& device) {
    std::string options;
    for (const CompilerWorkaround& workaround : compiler_workarounds(device)) {
        options += (options.empty() ? "-D" : " -D") + workaround.define;
    }
    return options;
}

}  // namespace rc
