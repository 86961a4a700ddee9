// What a device lacks that radcache's kernels would use (`radcache devices`): the extensions its
// OpenCL C compiler defines (a driver may list one its compiler does not define: Mesa's rusticl
// lists cl_khr_int64_base_atomics), and whether its profiling events measure kernel time.
#pragma once

#include <string>
#include <vector>

namespace rc {

class Context;

struct DeviceFeatures {
    bool fp64 = false;           // cl_khr_fp64 defined by the compiler
    bool int64_atomics = false;  // cl_khr_int64_base_atomics defined by the compiler
    bool profiling = false;      // its events measure a launch (not 0 or 1 ns)
};

// Builds and runs kernels/device_features.cl on `context`'s device.
DeviceFeatures probe_device_features(Context& context);

// What the device lacks, each with what radcache does without it; empty when nothing.
std::vector<std::string> lacking(const DeviceFeatures& features);

}  // namespace rc
