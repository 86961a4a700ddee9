// Defects of an OpenCL implementation's compiler that radcache's kernels work around, and the
// defines a program is built with to do so (docs/devices.md, "Compiler workarounds"). Each is a
// measured miscompilation of code OpenCL defines, never a difference the specification allows.
#pragma once

#include <string>
#include <vector>

#include "device/device_list.h"

namespace rc {

struct CompilerWorkaround {
    std::string define;  // passed as -D<define> to every program built for the device
    std::string reason;  // one line: what the compiler gets wrong without it
};

// The workarounds `device` needs: on Intel's CPU runtime (platform "Intel(R) OpenCL"), every
// kernel compiled one work item at a time (RC_SCALAR_WORK_ITEMS, kernels/shared/compat.h): its
// vectoriser returns a float3 from an out-of-line function shifted by one component, and its
// scalar code for small work groups rounds differently from its vector code. None with
// $RADCACHE_NO_COMPILER_WORKAROUNDS=1 (to check whether a newer driver still needs them).
std::vector<CompilerWorkaround> compiler_workarounds(const DeviceInfo& device);

// The workarounds' defines as build options ("-DA -DB"), empty when there are none.
std::string compiler_workaround_options(const DeviceInfo& device);

}  // namespace rc
