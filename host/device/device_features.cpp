#include "device/device_features.h"

#include "device/context.h"

namespace rc {

DeviceFeatures probe_device_features(Context& context) {
    DeviceFeatures features;
    Kernel probe = context.kernel("device_features.cl", "device_features");
    Buffer<int> out(context, 1, "device_features");
    context.launch(probe, 1, out);
    const int bits = out.download().at(0);
    features.fp64 = (bits & 1) != 0;
    features.int64_atomics = (bits & 2) != 0;
    // Enough launches for the timer to show: Context::launch takes the host's time for any launch
    // whose events measure under a thousandth of it.
    constexpr size_t kItems = size_t{1} << 16;
    Kernel busy = context.kernel("device_features.cl", "device_busy");
    Buffer<float> sink(context, kItems, "device_busy");
    context.launch(busy, kItems, sink);
    context.finish();
    const auto found = context.kernel_times().find("device_busy");
    features.profiling = found != context.kernel_times().end() && found->second.host_timed == 0;
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
    return lacks;
}

}  // namespace rc
