#include "device/memory_need.h"

#include <cstdio>

#include "device/context.h"
#include "util/error.h"

namespace rc {
namespace {

// "12 B", "3.65 KiB", "6.00 MiB".
std::string format_size(uint64_t bytes) {
    if (bytes >= 1024 * 1024) {
        return format_mebibytes(bytes);
    }
    if (bytes < 1024) {
        return std::to_string(bytes) + " B";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.2f KiB", static_cast<double>(bytes) / 1024.0);
    return text;
}

}  // namespace

void DeviceMemoryNeed::add_all(const DeviceMemoryNeed& other, const std::string& prefix) {
    for (const Part& part : other.parts) {
        add(prefix + part.name, part.bytes);
    }
    if (!other.excludes.empty()) {
        excludes += (excludes.empty() ? "" : ", ") + other.excludes;
    }
}

uint64_t DeviceMemoryNeed::total() const {
    uint64_t bytes = 0;
    for (const Part& part : parts) {
        bytes += part.bytes;
    }
    return bytes;
}

std::string DeviceMemoryNeed::describe() const {
    std::string text;
    for (const Part& part : parts) {
        text += (text.empty() ? "" : ", ") + part.name + " " + format_size(part.bytes);
    }
    return text;
}

DeviceMemoryNeed peak_of(const DeviceMemoryNeed& a, const DeviceMemoryNeed& b) {
    DeviceMemoryNeed peak = a.total() >= b.total() ? a : b;
    const DeviceMemoryNeed& other = a.total() >= b.total() ? b : a;
    if (!other.excludes.empty() && peak.excludes.find(other.excludes) == std::string::npos) {
        peak.excludes += (peak.excludes.empty() ? "" : ", ") + other.excludes;
    }
    return peak;
}

std::string format_mebibytes(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
    return text;
}

void check_device_memory_need(const Context& context, const DeviceMemoryNeed& need) {
    const uint64_t limit = context.memory_limit();
    if (limit == 0 || need.total() <= limit) {
        return;
    }
    throw Error("the render needs " + std::string(need.excludes.empty() ? "" : "at least ") +
                format_mebibytes(need.total()) + " of device memory (" + need.describe() +
                (need.excludes.empty() ? "" : "; then " + need.excludes) + "), more than the " +
                format_mebibytes(limit) + " of " + context.memory_limit_source());
}

}  // namespace rc
