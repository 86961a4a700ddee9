#include "device/buffer.h"

#include <utility>

#include "device/cl_calls.h"
#include "device/cl_error.h"
#include "device/context.h"
#include "device/memory_need.h"
#include "util/error.h"

namespace rc {

DeviceBuffer::DeviceBuffer(Context& context, size_t bytes, std::string name)
    : context_(&context), bytes_(std::max<size_t>(bytes, 1)), name_(std::move(name)) {
    const DeviceInfo& device = context.device();
    if (bytes_ > device.max_allocation) {
        throw Error("buffer '" + name_ + "' needs " + format_mebibytes(bytes_) +
                    ", more than the largest allocation " +
                    format_mebibytes(device.max_allocation) + " of " + device.name);
    }
    // The device's memory (or --device-memory) bounds what a run holds at once: a render is
    // refused up front with its whole need (device/memory_need.h); what grows past it (caches)
    // is refused here, with the figures, rather than by the driver mid-launch.
    const size_t held = context.device_memory().in_use;
    const uint64_t limit = context.memory_limit();
    if (limit > 0 && held + bytes_ > limit) {
        throw Error("buffer '" + name_ + "' needs " + format_mebibytes(bytes_) + ": with the " +
                    format_mebibytes(held) + " this run holds, more than the " +
                    format_mebibytes(limit) + " of " + context.memory_limit_source());
    }
    cl_int status = CL_SUCCESS;
    handle_ = RC_CL_CREATE("buffer", clCreateBuffer, &status, context.cl_context(),
                           CL_MEM_READ_WRITE, bytes_, nullptr);
    check_cl(status, "clCreateBuffer", name_ + ", " + format_mebibytes(bytes_));
    memory_ = context.memory_counter();
    memory_->allocate(bytes_);
}

DeviceBuffer::~DeviceBuffer() { release(); }

void DeviceBuffer::release() {
    if (handle_ != nullptr) {
        RC_CL_RELEASE("buffer", clReleaseMemObject, handle_);
        handle_ = nullptr;
        memory_->release(bytes_);
    }
}

DeviceBuffer::DeviceBuffer(DeviceBuffer&& other) noexcept
    : context_(other.context_),
      memory_(std::move(other.memory_)),
      handle_(std::exchange(other.handle_, nullptr)),
      bytes_(std::exchange(other.bytes_, 0)),
      name_(std::move(other.name_)) {}

DeviceBuffer& DeviceBuffer::operator=(DeviceBuffer&& other) noexcept {
    if (this != &other) {
        release();
        context_ = other.context_;
        memory_ = std::move(other.memory_);
        handle_ = std::exchange(other.handle_, nullptr);
        bytes_ = std::exchange(other.bytes_, 0);
        name_ = std::move(other.name_);
    }
    return *this;
}

void DeviceBuffer::write(const void* data, size_t bytes, size_t offset) {
    if (bytes == 0) {
        return;
    }
    if (offset + bytes > bytes_) {
        throw Error("write of " + std::to_string(bytes) + " bytes past the end of buffer '" +
                    name_ + "'");
    }
    check_cl(RC_CL(clEnqueueWriteBuffer, context_->cl_queue(), handle_, CL_TRUE, offset, bytes,
                   data, 0, nullptr, nullptr),
             "clEnqueueWriteBuffer", name_);
}

void DeviceBuffer::read(void* data, size_t bytes, size_t offset) const {
    if (bytes == 0) {
        return;
    }
    if (offset + bytes > bytes_) {
        throw Error("read of " + std::to_string(bytes) + " bytes past the end of buffer '" + name_ +
                    "'");
    }
    check_cl(RC_CL(clEnqueueReadBuffer, context_->cl_queue(), handle_, CL_TRUE, offset, bytes, data,
                   0, nullptr, nullptr),
             "clEnqueueReadBuffer", name_);
}

void DeviceBuffer::fill_zero() {
    const unsigned char zero = 0;
    check_cl(RC_CL(clEnqueueFillBuffer, context_->cl_queue(), handle_, &zero, 1, 0, bytes_, 0,
                   nullptr, nullptr),
             "clEnqueueFillBuffer", name_);
    check_cl(RC_CL(clFinish, context_->cl_queue()), "clFinish", name_);
}

}  // namespace rc
