// Wall-clock time of the phases the statistics report. Include from .cpp files.
#pragma once

#include <chrono>

namespace rc {

using SteadyClock = std::chrono::steady_clock;

// Seconds from `start` until now.
inline double seconds_since(SteadyClock::time_point start) {
    return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

}  // namespace rc
