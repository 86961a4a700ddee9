// Work shared among several devices (issue 14; FrameScene::peers): items 0 .. count - 1 (pixel
// chunks, photon batches) taken in turn by one thread per device as it finishes its last, so
// faster devices take more; device i takes item i first, so each does at least one when there
// are enough. What an item computes must not depend on the device that takes it; the caller
// merges the devices' results by item (or, for sums exact in any order, as they come).
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "device/context.h"

namespace rc {

struct DeviceSplit {
    std::vector<std::vector<size_t>> items;  // per device, in the order it took them
    std::vector<double> seconds;             // per device: its thread's time
};

// Runs `work(device, item, stop)` for every item over `devices` (one thread each); `progress`
// (may be empty) is called on this thread with the fraction done while they run. `stop` turns
// true once any item failed: a long item may end early. The first failure is rethrown as an
// Error (its exit status kept) prefixed "device P:D (NAME): ", after every thread has ended.
DeviceSplit run_device_split(
    const std::vector<Context*>& devices, size_t count,
    const std::function<void(size_t device, size_t item, const std::atomic<bool>& stop)>& work,
    const std::function<void(double fraction)>& progress);

}  // namespace rc
