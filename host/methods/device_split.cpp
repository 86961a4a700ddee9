#include "methods/device_split.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "util/error.h"
#include "util/timing.h"

namespace rc {
namespace {

// What the device threads share: the next item, how many are done, the first failure, and each
// device's speed (items per second: the given one, then its own once it finished an item) and
// whether it still takes items. `next`, `speed` and `taking` change under `mutex`.
struct SplitQueue {
    size_t count = 0;
    size_t next = 0;
    std::atomic<size_t> done{0};
    std::atomic<bool> failed{false};
    std::mutex mutex;
    std::condition_variable changed;  // an item done or failed
    std::string error;
    int exit_code = kExitFailure;
    std::vector<double> speed;   // 0: not known
    std::vector<bool> measured;  // speed is this split's
    std::vector<bool> taking;

    // The next item for `device`, or count when it takes no more: none left, or a faster device
    // that still takes items would finish every item left (this one included) before `device`
    // finished one.
    size_t take(size_t device) {
        const std::lock_guard<std::mutex> lock(mutex);
        const size_t left = next < count ? count - next : 0;
        bool yield = left == 0;
        for (size_t other = 0; other < speed.size() && !yield; ++other) {
            yield = other != device && taking[other] && speed[device] > 0.0 &&
                    speed[other] > static_cast<double>(left) * speed[device];
        }
        if (yield) {
            taking[device] = false;
            return count;
        }
        return next++;
    }

    // `device`'s speed measured on this split's items. A given speed is of an earlier split's
    // items (of another size): the first measurement scales the speeds not yet measured alike,
    // so that their ratios hold in this split's units.
    void finished_item(size_t device, double items_per_second) {
        {
            // Through the mutex, so that the waiting thread cannot miss the notification.
            const std::lock_guard<std::mutex> lock(mutex);
            if (!measured[device] && speed[device] > 0.0) {
                const double scale = items_per_second / speed[device];
                for (size_t other = 0; other < speed.size(); ++other) {
                    speed[other] *= measured[other] ? 1.0 : scale;
                }
            }
            speed[device] = items_per_second;
            measured[device] = true;
            ++done;
        }
        changed.notify_one();
    }
};

void run_device(size_t index, const Context& context, SplitQueue& queue, bool reserved_first,
                const std::function<void(size_t, size_t, const std::atomic<bool>&)>& work,
                std::vector<size_t>& items, double& seconds) {
    const auto start = SteadyClock::now();
    try {
        size_t item = reserved_first ? index : queue.take(index);
        while (item < queue.count && !queue.failed) {
            work(index, item, queue.failed);
            if (queue.failed) {
                break;
            }
            items.push_back(item);
            queue.finished_item(
                index, static_cast<double>(items.size()) / std::max(seconds_since(start), 1e-9));
            item = queue.take(index);
        }
    } catch (const std::exception& e) {
        const std::lock_guard<std::mutex> lock(queue.mutex);
        if (!queue.failed.exchange(true)) {
            queue.error = "device " + context.device().spec() + " (" + context.device().name +
                          "): " + e.what();
            const auto* error = dynamic_cast<const Error*>(&e);
            queue.exit_code = error != nullptr ? error->exit_code() : kExitFailure;
        }
        queue.changed.notify_one();
    }
    seconds = seconds_since(start);
}

}  // namespace

PixelChunks::PixelChunks(int width, int height, size_t devices, int per_device)
    : pixels(static_cast<size_t>(width) * static_cast<size_t>(height)) {
    const int rows = std::max(1, height / std::max(1, per_device * static_cast<int>(devices)));
    chunk_pixels = std::max<size_t>(1, static_cast<size_t>(rows) * static_cast<size_t>(width));
    count = (pixels + chunk_pixels - 1) / chunk_pixels;
}

std::pair<size_t, size_t> PixelChunks::range(size_t chunk) const {
    return {chunk * chunk_pixels, std::min(pixels, (chunk + 1) * chunk_pixels)};
}

ItemRanges::ItemRanges(size_t count, size_t devices, size_t per_device, size_t smallest)
    : items(count) {
    const size_t ranges = std::max<size_t>(1, per_device * devices);
    range_items = std::max({size_t{1}, smallest, (count + ranges - 1) / ranges});
    this->count = (count + range_items - 1) / range_items;
}

std::pair<size_t, size_t> ItemRanges::range(size_t range) const {
    return {range * range_items, std::min(items, (range + 1) * range_items)};
}

DeviceSplit run_device_split(
    const std::vector<Context*>& devices, size_t count,
    const std::function<void(size_t device, size_t item, const std::atomic<bool>& stop)>& work,
    const std::function<void(double fraction)>& progress, const std::vector<double>& speeds) {
    SplitQueue queue;
    queue.count = count;
    const bool known = speeds.size() == devices.size() &&
                       std::all_of(speeds.begin(), speeds.end(), [](double s) { return s > 0.0; });
    // Without speeds, items 0 .. devices - 1 are the devices' first.
    queue.next = known ? 0 : std::min(count, devices.size());
    queue.speed = known ? speeds : std::vector<double>(devices.size(), 0.0);
    queue.measured.assign(devices.size(), false);
    queue.taking.assign(devices.size(), true);
    DeviceSplit split;
    split.items.resize(devices.size());
    split.seconds.resize(devices.size());
    std::vector<std::thread> threads;
    for (size_t i = 0; i < devices.size(); ++i) {
        threads.emplace_back(run_device, i, std::cref(*devices[i]), std::ref(queue), !known,
                             std::cref(work), std::ref(split.items[i]), std::ref(split.seconds[i]));
    }
    // Progress every 50 ms until the last item is done (woken at once then: short splits
    // return as soon as their items are).
    const auto finished = [&] { return queue.done >= count || queue.failed; };
    while (!finished()) {
        if (progress) {
            progress(static_cast<double>(queue.done) / static_cast<double>(count));
        }
        std::unique_lock<std::mutex> lock(queue.mutex);
        queue.changed.wait_for(lock, std::chrono::milliseconds(50), finished);
    }
    for (std::thread& thread : threads) {
        thread.join();
    }
    if (queue.failed) {
        throw Error(queue.error, queue.exit_code);
    }
    return split;
}

}  // namespace rc
