// Device memory: an untyped buffer with checked, named transfers, and a typed view of it.
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

struct _cl_mem;

namespace rc {

class Context;
struct DeviceMemory;

class DeviceBuffer {
   public:
    DeviceBuffer() = default;
    // Allocates `bytes` (at least 1) after checking them against the device's limits; the name
    // appears in every error about this buffer.
    DeviceBuffer(Context& context, size_t bytes, std::string name);
    ~DeviceBuffer();
    DeviceBuffer(DeviceBuffer&& other) noexcept;
    DeviceBuffer& operator=(DeviceBuffer&& other) noexcept;
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;

    // Blocking transfers of `bytes` at byte `offset`.
    void write(const void* data, size_t bytes, size_t offset = 0);
    void read(void* data, size_t bytes, size_t offset = 0) const;
    void fill_zero();

    size_t bytes() const { return bytes_; }
    const std::string& name() const { return name_; }
    _cl_mem* handle() const { return handle_; }

   private:
    void release();

    Context* context_ = nullptr;
    std::shared_ptr<DeviceMemory> memory_;  // the context's bookkeeping, which this may outlive
    _cl_mem* handle_ = nullptr;
    size_t bytes_ = 0;
    std::string name_;
};

template <class T>
class Buffer : public DeviceBuffer {
   public:
    Buffer() = default;
    Buffer(Context& context, size_t count, std::string name)
        : DeviceBuffer(context, std::max<size_t>(count, 1) * sizeof(T), std::move(name)),
          count_(count) {}
    Buffer(Context& context, const std::vector<T>& values, std::string name)
        : Buffer(context, values.size(), std::move(name)) {
        upload(values);
    }

    size_t size() const { return count_; }

    void upload(const std::vector<T>& values) {
        write(values.data(), std::min(values.size(), count_) * sizeof(T));
    }
    std::vector<T> download() const {
        std::vector<T> values(count_);
        read(values.data(), count_ * sizeof(T));
        return values;
    }

   private:
    size_t count_ = 0;
};

}  // namespace rc
