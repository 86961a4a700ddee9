// The process's host memory, for --stats (Linux: /proc/self/status).
#pragma once

#include <cstdint>

namespace rc {

struct HostMemory {
    uint64_t resident = 0;       // bytes resident now (VmRSS)
    uint64_t peak_resident = 0;  // the most resident since the last reset (VmHWM)
};

// Zeros where the figures cannot be read.
HostMemory host_memory();

// Starts a new peak (VmHWM restarts from the current resident size); false where the kernel
// does not allow it.
bool reset_host_memory_peak();

}  // namespace rc
