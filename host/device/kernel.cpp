#include "device/kernel.h"

#include <utility>

#include "device/cl_calls.h"
#include "device/cl_error.h"

namespace rc {

Kernel::Kernel(_cl_kernel* handle, std::string name) : handle_(handle), name_(std::move(name)) {}

Kernel::~Kernel() {
    if (handle_ != nullptr) {
        RC_CL_RELEASE("kernel", clReleaseKernel, handle_);
    }
}

Kernel::Kernel(Kernel&& other) noexcept
    : handle_(std::exchange(other.handle_, nullptr)), name_(std::move(other.name_)) {}

Kernel& Kernel::operator=(Kernel&& other) noexcept {
    if (this != &other) {
        if (handle_ != nullptr) {
            RC_CL_RELEASE("kernel", clReleaseKernel, handle_);
        }
        handle_ = std::exchange(other.handle_, nullptr);
        name_ = std::move(other.name_);
    }
    return *this;
}

void Kernel::set_arg(unsigned index, size_t size, const void* value) {
    check_cl(RC_CL(clSetKernelArg, handle_, index, size, value), "clSetKernelArg",
             name_ + " argument " + std::to_string(index));
}

size_t Kernel::max_work_group_size(_cl_device_id* device) const {
    size_t size = 0;
    check_cl(RC_CL(clGetKernelWorkGroupInfo, handle_, device, CL_KERNEL_WORK_GROUP_SIZE,
                   sizeof size, &size, nullptr),
             "clGetKernelWorkGroupInfo", name_);
    return size;
}

}  // namespace rc
