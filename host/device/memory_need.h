// The device memory a render will hold in buffers at its peak, part by part (the scene, its BVH,
// the method's buffers), computed from the scene and the options before any buffer is made, so
// that a render that cannot fit is refused up front with its whole figure (docs/reliability.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rc {

class Context;

struct DeviceMemoryNeed {
    struct Part {
        std::string name;  // "scene", "bvh", "film", ...
        uint64_t bytes = 0;
    };
    std::vector<Part> parts;
    // What the figure leaves out, named by a method whose caches grow with what it finds (records
    // and their batches, a grid file): the figure is then the least the render needs (the
    // buffers every such render holds together), and what those add is checked buffer by buffer
    // as they are made. Empty: the figure is the render's peak.
    std::string excludes;

    void add(std::string name, uint64_t bytes) { parts.push_back({std::move(name), bytes}); }
    // Adds `other`'s parts (and what it excludes) under `prefix`.
    void add_all(const DeviceMemoryNeed& other, const std::string& prefix = "");
    uint64_t total() const;
    // "scene 1.21 MiB, BVH 540.00 KiB, film 6.00 MiB, counters 12 B"
    std::string describe() const;
};

// The need of a run whose phases hold `a` and `b` at different times: the larger, with what
// either excludes.
DeviceMemoryNeed peak_of(const DeviceMemoryNeed& a, const DeviceMemoryNeed& b);

// The bytes a Buffer<T> of `count` elements of `element` bytes allocates (at least one element).
inline uint64_t buffer_bytes(size_t count, size_t element) {
    return static_cast<uint64_t>(count > 0 ? count : 1) * element;
}

std::string format_mebibytes(uint64_t bytes);  // "2.00 MiB"

// Refuses (Error, exit status 1) a render whose need is more than the context's limit (the
// device's global memory, or --device-memory): the figure, its parts and the limit in one line.
void check_device_memory_need(const Context& context, const DeviceMemoryNeed& need);

}  // namespace rc
