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
    // Intel's CPU runtime (2026.2, measured: docs/lab/devices.md, "Intel's CPU runtime"): a
    // device function it keeps out of line and vectorises across work items (a masked vector
    // variant, _ZGVeM16...) hands a float3 result to its caller one component late, (x, y, z)
    // arriving as (?, x, y); with -cl-opt-disable, or every function inlined, it is right.
    if (device.platform_name == "Intel(R) OpenCL" && device.is_cpu && !workarounds_disabled()) {
        workarounds.push_back(
            {"RC_INLINE_EVERY_FUNCTION",
             "every device function inlined: Intel's CPU compiler returns a "
             "float3 from an out-of-line vectorised function one component late"});
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
