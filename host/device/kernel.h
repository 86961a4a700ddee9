// One OpenCL kernel object and its name (the name every error and timing refers to).
#pragma once

#include <string>

struct _cl_kernel;
struct _cl_device_id;

namespace rc {

class Kernel {
   public:
    Kernel() = default;
    Kernel(_cl_kernel* handle, std::string name);
    ~Kernel();
    Kernel(Kernel&& other) noexcept;
    Kernel& operator=(Kernel&& other) noexcept;
    Kernel(const Kernel&) = delete;
    Kernel& operator=(const Kernel&) = delete;

    const std::string& name() const { return name_; }
    _cl_kernel* handle() const { return handle_; }

    // clSetKernelArg, checked and reported with the kernel's name and the argument index.
    void set_arg(unsigned index, size_t size, const void* value);

    // The largest work-group size the device allows for this kernel.
    size_t max_work_group_size(_cl_device_id* device) const;

   private:
    _cl_kernel* handle_ = nullptr;
    std::string name_;
};

// Several consecutive kernel arguments that travel together (the scene's buffers, say):
// Context::launch calls set_kernel_args with the index of the first, and it returns how many it
// set.
class KernelArgumentGroup {
   public:
    virtual ~KernelArgumentGroup() = default;
    virtual unsigned set_kernel_args(Kernel& kernel, unsigned first) const = 0;
};

}  // namespace rc
