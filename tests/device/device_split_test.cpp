// Work shared among devices (methods/device_split.h): every item is done exactly once whatever
// the devices' speeds; without speeds each device takes an item first; given speeds, a device
// does not take an item that a faster device would finish, with every item left, before it
// finished that one (a device 9 times slower takes none of 8 items, one 3 times slower some, but
// not the last).
// The work here is host code standing for a device's: the rule reads the given speeds at the
// start, so what each device takes first does not depend on the clock.
#include "methods/device_split.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "test_support.h"

namespace rc {
namespace {

// Runs `count` items over two "devices" (the shared context twice); device 1's items take
// `slowdown` times device 0's. Returns which device did each item (asserting each was done once).
std::vector<int> split_items(size_t count, double slowdown, const std::vector<double>& speeds,
                             DeviceSplit* out = nullptr) {
    Context& context = test::shared_context();
    std::vector<std::atomic<int>> done(count);
    for (auto& d : done) {
        d = -1;
    }
    const DeviceSplit split = run_device_split(
        {&context, &context}, count,
        [&](size_t device, size_t item, const std::atomic<bool>&) {
            const double ms = device == 0 ? 2.0 : 2.0 * slowdown;
            std::this_thread::sleep_for(std::chrono::microseconds(static_cast<int>(ms * 1000)));
            int expected = -1;
            EXPECT_TRUE(done[item].compare_exchange_strong(expected, static_cast<int>(device)))
                << "item " << item << " done twice";
        },
        {}, speeds);
    std::vector<int> by(count);
    for (size_t i = 0; i < count; ++i) {
        by[i] = done[i];
        EXPECT_GE(by[i], 0) << "item " << i << " not done";
    }
    if (out != nullptr) {
        *out = split;
    }
    return by;
}

TEST(DeviceSplit, WithoutSpeedsEveryDeviceTakesAnItemFirstAndEveryItemIsDoneOnce) {
    DeviceSplit split;
    const std::vector<int> by = split_items(8, 9.0, {}, &split);
    EXPECT_EQ(by[0], 0);
    EXPECT_EQ(by[1], 1);
    EXPECT_EQ(split.items[0].size() + split.items[1].size(), 8u);
}

TEST(DeviceSplit, ADeviceNineTimesSlowerTakesNoneOfEightItems) {
    DeviceSplit split;
    const std::vector<int> by = split_items(8, 9.0, {9.0, 1.0}, &split);
    EXPECT_TRUE(split.items[1].empty()) << "the slow device took " << split.items[1].size();
    EXPECT_EQ(std::count(by.begin(), by.end(), 0), 8);
}

TEST(DeviceSplit, ADeviceThreeTimesSlowerTakesSomeButNotTheLast) {
    DeviceSplit split;
    split_items(16, 3.0, {3.0, 1.0}, &split);
    // It takes its first item (16 left) and no item once fewer than 3 are left (its speed and
    // the other's then measured, about 3 times apart): never the last.
    EXPECT_FALSE(split.items[1].empty());
    for (size_t item : split.items[1]) {
        EXPECT_LT(item, 15u) << "the slow device took the last item";
    }
}

TEST(DeviceSplit, FewerItemsThanDevicesAreEachDoneOnce) {
    split_items(1, 1.0, {});
    split_items(1, 1.0, {1.0, 1.0});
    split_items(0, 1.0, {1.0, 1.0});
}

}  // namespace
}  // namespace rc
