// Host work split over threads: contiguous ranges of an index space, one per thread, the first on
// the calling thread. For work whose result does not depend on how it is split (each range
// writes only its own output); an exception thrown by any range is rethrown after every thread
// has joined.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace rc {

// The host's threads for such work: the hardware's (at least 1).
inline unsigned host_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

// Calls body(begin, end, part) for `parts` ranges covering [0, count) in order (fewer when count
// is smaller); part 0 runs on the calling thread.
template <class Body>
void parallel_ranges(size_t count, unsigned parts, Body&& body) {
    const size_t n = std::max<size_t>(1, std::min<size_t>(parts, count));
    const auto range = [&](size_t part) {
        return std::pair<size_t, size_t>{count * part / n, count * (part + 1) / n};
    };
    std::vector<std::exception_ptr> errors(n);
    std::vector<std::thread> threads;
    for (size_t part = 1; part < n; ++part) {
        threads.emplace_back([&, part] {
            try {
                const auto [begin, end] = range(part);
                body(begin, end, part);
            } catch (...) {
                errors[part] = std::current_exception();
            }
        });
    }
    try {
        const auto [begin, end] = range(0);
        body(begin, end, size_t{0});
    } catch (...) {
        errors[0] = std::current_exception();
    }
    for (std::thread& thread : threads) {
        thread.join();
    }
    for (const std::exception_ptr& error : errors) {
        if (error) {
            std::rethrow_exception(error);
        }
    }
}

// Calls body(i, part) for every i of [0, count) on `parts` threads (fewer when count is smaller),
// handing out `chunk` indices at a time to whichever thread is free: for items of uneven cost.
// Which part runs an item is not deterministic: body's result must not depend on it.
template <class Body>
void parallel_items(size_t count, unsigned parts, size_t chunk, Body&& body) {
    std::atomic<size_t> next{0};
    parallel_ranges(parts, parts, [&](size_t, size_t, size_t part) {
        for (size_t begin = next.fetch_add(chunk); begin < count; begin = next.fetch_add(chunk)) {
            for (size_t i = begin; i < std::min(count, begin + chunk); ++i) {
                body(i, part);
            }
        }
    });
}

}  // namespace rc
