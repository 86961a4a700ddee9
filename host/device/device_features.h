// What a device lacks that radcache's kernels would use (`radcache devices`): the extensions its
// OpenCL C compiler defines (a driver may list one its compiler does not define: Mesa's rusticl
// lists cl_khr_int64_base_atomics), whether its profiling events measure kernel time, and whether
// it ends a work item's loops early (Mesa's llvmpipe: after 65535 iterations of all its loops
// together, gallivm's LP_MAX_TGSI_LOOP_ITERATIONS, every loop of the item runs at most once).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rc {

class Context;

struct DeviceFeatures {
    bool fp64 = false;                 // cl_khr_fp64 defined by the compiler
    bool int64_atomics = false;        // cl_khr_int64_base_atomics defined by the compiler
    bool profiling = false;            // its events measure a launch (not 0 or 1 ns)
    std::optional<uint32_t> loop_cap;  // iterations a work item's loops ran before they ended
};

// Iterations of a loop that the probe runs to the end (kLoopProbeIterations) or, on a device
// that ends loops early, how many it ran; none where it ran them all.
inline constexpr uint32_t kLoopProbeIterations = uint32_t{1} << 22;
std::optional<uint32_t> probe_loop_cap(Context& context);

// The program the loop probe builds: a render's and warmup's programs include it.
inline constexpr const char* kDeviceFeaturesProgram = "device_features.cl";

// Error (exit status 2) naming the device and its cap where `context`'s device ends loops early
// (probe_loop_cap): radcache's kernels loop longer than that, and their images would be wrong.
// `--allow-loop-cap` (ContextOptions::allow_loop_cap) renders there anyway, unprobed. Clears
// the context's kernel times (the probe's launch is not the work's).
void refuse_loop_capped_device(Context& context);

// Builds and runs kernels/device_features.cl on `context`'s device.
DeviceFeatures probe_device_features(Context& context);

// What the device lacks, each with what radcache does without it; empty when nothing.
std::vector<std::string> lacking(const DeviceFeatures& features);

}  // namespace rc
