#include "util/host_memory.h"

#include <fstream>
#include <sstream>
#include <string>

namespace rc {

HostMemory host_memory() {
    HostMemory memory;
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);) {
        std::istringstream fields(line);
        std::string key;
        uint64_t kib = 0;
        if (!(fields >> key >> kib)) {
            continue;
        }
        if (key == "VmRSS:") {
            memory.resident = kib * 1024;
        } else if (key == "VmHWM:") {
            memory.peak_resident = kib * 1024;
        }
    }
    return memory;
}

bool reset_host_memory_peak() {
    // "5" resets the peak resident set size (Documentation/filesystems/proc.rst, clear_refs).
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.close();
    return static_cast<bool>(clear);
}

}  // namespace rc
