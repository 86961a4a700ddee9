// Work shared among several devices (FrameScene::peers): items 0 .. count - 1 (pixel
// chunks, photon batches) taken in turn by one thread per device as it finishes its last, so
// faster devices take more; device i takes item i first, so each does at least one when there
// are enough. Given the devices' relative speeds (from an earlier split), or once both have
// finished an item of this one, a device does not take an item that a faster device still taking
// items would finish, with every item left, before it finished that one: the split never waits on
// a slow device's last item longer than the faster devices take for what is left (a CPU beside a
// GPU, rusticl beside PoCL). What an item computes must not depend on the device that takes it;
// the caller merges the devices' results by item (or, for sums exact in any order, as they
// come).
#pragma once

#include <algorithm>
#include <atomic>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "device/context.h"

namespace rc {

struct DeviceSplit {
    std::vector<std::vector<size_t>> items;  // per device, in the order it took them
    std::vector<double> seconds;             // per device: its thread's time
};

// An image's pixels [0, width x height) in chunks of whole rows, about `per_device` chunks for
// each of `devices` (the work items of a split over pixels).
struct PixelChunks {
    PixelChunks(int width, int height, size_t devices, int per_device = 16);
    // Pixels [first, second) of chunk `chunk`.
    std::pair<size_t, size_t> range(size_t chunk) const;

    size_t pixels = 0;
    size_t chunk_pixels = 1;
    size_t count = 0;
};

// Items [0, count) (records, clusters, triangles) in ranges of equal size, about `per_device`
// ranges for each of `devices` and none smaller than `smallest` items (the work items of a split
// over items; the last range may be shorter).
struct ItemRanges {
    ItemRanges(size_t count, size_t devices, size_t per_device, size_t smallest = 1);
    // Items [first, second) of range `range`.
    std::pair<size_t, size_t> range(size_t range) const;

    size_t items = 0;
    size_t range_items = 1;
    size_t count = 0;  // ranges
};

// Copies the pixels (`slots` values each) of `chunks` from `film`, a device's film of the whole
// image, into the same place of `image`; returns how many pixels that is.
template <class T>
size_t copy_chunks(const PixelChunks& pixels, const std::vector<size_t>& chunks,
                   const std::vector<T>& film, size_t slots, std::vector<T>& image) {
    size_t copied = 0;
    for (size_t chunk : chunks) {
        const auto [begin, end] = pixels.range(chunk);
        std::copy(film.begin() + static_cast<long>(begin * slots),
                  film.begin() + static_cast<long>(end * slots),
                  image.begin() + static_cast<long>(begin * slots));
        copied += end - begin;
    }
    return copied;
}

// Runs `work(device, item, stop)` for every item over `devices` (one thread each); `progress`
// (may be empty) is called on this thread with the fraction done while they run. `stop` turns
// true once any item failed: a long item may end early. The first failure is rethrown as an
// Error (its exit status kept) prefixed "device P:D (NAME): ", after every thread has ended.
// `speeds` (empty, or one per device, > 0): the devices' items per second in an earlier split
// (relative figures suffice); with them no item is reserved for a device at the start.
DeviceSplit run_device_split(
    const std::vector<Context*>& devices, size_t count,
    const std::function<void(size_t device, size_t item, const std::atomic<bool>& stop)>& work,
    const std::function<void(double fraction)>& progress, const std::vector<double>& speeds = {});

}  // namespace rc
