#include "device/device_features.h"

#include "device/context.h"
#include "util/error.h"

namespace rc {

namespace {

constexpr uint32_t kLcgMultiplier = 1664525u;  // kernels/device_features.cl's LCG
constexpr uint32_t kLcgIncrement = 1013904223u;

// x after `steps` steps of the LCG from `seed`, in O(log steps): the map x -> a x + c composed
// with itself (a^2 x + a c + c) for each bit of `steps`.
uint32_t lcg_after(uint32_t seed, uint32_t steps) {
    uint32_t a = kLcgMultiplier;
    uint32_t c = kLcgIncrement;
    uint32_t x = seed;
    for (; steps != 0; steps >>= 1) {
        if ((steps & 1u) != 0) {
            x = a * x + c;
        }
        c = a * c + c;
        a = a * a;
    }
    return x;
}

}  // namespace

std::optional<uint32_t> probe_loop_cap(Context& context) {
    constexpr uint32_t kSeed = 12345u;
    Kernel probe = context.kernel(kDeviceFeaturesProgram, "device_loop_cap");
    Buffer<uint32_t> out(context, 1, "device_loop_cap");
    context.launch(probe, 1, kLoopProbeIterations, kSeed, out);
    const uint32_t found = out.download().at(0);
    if (found == lcg_after(kSeed, kLoopProbeIterations)) {
        return std::nullopt;
    }
    // The host's own steps: the first that gives the device's value is how many the device's loop
    // ran (the LCG's period is 2^32, so the step is unique).
    uint32_t x = kSeed;
    for (uint32_t step = 0; step < kLoopProbeIterations; ++step) {
        if (x == found) {
            return step;
        }
        x = x * kLcgMultiplier + kLcgIncrement;
    }
    throw Error("the loop probe on " + context.device().name +
                " returned a value no run of its loop gives: the device miscomputes");
}

void refuse_loop_capped_device(Context& context) {
    if (context.options().allow_loop_cap) {
        return;
    }
    if (const std::optional<uint32_t> cap = probe_loop_cap(context)) {
        throw Error("device " + context.device().spec() + " (" + context.device().name +
                        ") ends a work item's loops after " + std::to_string(*cap) +
                        " iterations in all, and radcache's kernels loop longer: its results " +
                        "would be wrong (--allow-loop-cap renders there anyway; docs/devices.md)",
                    kExitUsage);
    }
    context.reset_kernel_times();  // the probe's launch is not the work's
}

DeviceFeatures probe_device_features(Context& context) {
    DeviceFeatures features;
    Kernel probe = context.kernel(kDeviceFeaturesProgram, "device_features");
    Buffer<int> out(context, 1, "device_features");
    context.launch(probe, 1, out);
    const int bits = out.download().at(0);
    features.fp64 = (bits & 1) != 0;
    features.int64_atomics = (bits & 2) != 0;
    // Enough launches for the timer to show: Context::launch takes the host's time for any launch
    // whose events measure under a thousandth of it.
    constexpr size_t kItems = size_t{1} << 16;
    Kernel busy = context.kernel(kDeviceFeaturesProgram, "device_busy");
    Buffer<float> sink(context, kItems, "device_busy");
    context.launch(busy, kItems, sink);
    context.finish();
    const auto found = context.kernel_times().find("device_busy");
    features.profiling = found != context.kernel_times().end() && found->second.host_timed == 0;
    features.loop_cap = probe_loop_cap(context);
    return features;
}

std::vector<std::string> lacking(const DeviceFeatures& features) {
    std::vector<std::string> lacks;
    if (!features.fp64) {
        lacks.push_back(
            "cl_khr_fp64 (ray-triangle edge tests that round to zero are not redone in double)");
    }
    if (!features.int64_atomics) {
        lacks.push_back(
            "cl_khr_int64_base_atomics in its compiler (ivg, ivg-gather and decomposition add "
            "their 64-bit sums with two 32-bit atomics)");
    }
    if (!features.profiling) {
        lacks.push_back("event profiling (kernel times in --stats are the host's, per launch)");
    }
    if (features.loop_cap) {
        lacks.push_back("loops past " + std::to_string(*features.loop_cap) +
                        " iterations per work item (it ends them early: radcache renders there "
                        "only with --allow-loop-cap)");
    }
    return lacks;
}

}  // namespace rc
