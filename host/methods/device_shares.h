// The results of a render shared among devices (methods/device_split.h) put together: the first
// pixel with a non-finite sample over the devices, and each device's share in the stats.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

namespace rc {

// The first pixel with a non-finite sample of two parts of the work (-1: the part has none): the
// smaller of the two found.
inline int64_t first_nonfinite_of(int64_t a, int64_t b) {
    return a < 0 ? b : (b < 0 || a < b ? a : b);
}

// The stats' "devices" array: `row(share)`, a JSON object of one device's share, for each of
// `shares` (the first device first) into (*stats)["devices"]; nothing when the render ran on one
// device (no shares).
template <class Share, class Row>
void add_device_shares(const std::vector<Share>& shares, nlohmann::json* stats, const Row& row) {
    if (shares.empty()) {
        return;
    }
    nlohmann::json devices = nlohmann::json::array();
    for (const Share& share : shares) {
        devices.push_back(row(share));
    }
    (*stats)["devices"] = devices;
}

}  // namespace rc
