#include "device/context.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "device/cl_calls.h"
#include "device/cl_error.h"
#include "device/compiler_workarounds.h"
#include "util/error.h"

namespace rc {
namespace {

constexpr size_t kDefaultMaxChunkItems = size_t{1} << 20;
constexpr size_t kFirstChunkItems = size_t{1} << 16;
constexpr size_t kPreferredLocalSize = 64;
// A profiled kernel duration below this fraction of the host's enqueue-to-completion time is
// taken as unmeasured.
constexpr double kImplausibleProfileRatio = 1000.0;

std::filesystem::path kernel_dir_option(const ContextOptions& options) {
    if (!options.kernel_dir.empty()) {
        return options.kernel_dir;
    }
    if (const char* dir = std::getenv("RADCACHE_KERNEL_DIR"); dir != nullptr && *dir != '\0') {
        return dir;
    }
    return {};
}

size_t round_up(size_t value, size_t multiple) {
    return (value + multiple - 1) / multiple * multiple;
}

}  // namespace

Context::Context(const ContextOptions& options)
    : options_(options),
      device_(select_device(list_devices(), options.device_spec)),
      bvh_layout_(options.bvh_layout.value_or(default_bvh_layout())),
      sources_(kernel_dir_option(options)),
      cache_(options.cache_dir) {
    cl_int status = CL_SUCCESS;
    const cl_context_properties properties[] = {
        CL_CONTEXT_PLATFORM, reinterpret_cast<cl_context_properties>(device_.platform), 0};
    context_ = RC_CL_CREATE("context", clCreateContext, &status, properties, 1, &device_.device,
                            nullptr, nullptr);
    check_cl(status, "clCreateContext", device_.name);
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    queue_ = RC_CL_CREATE("queue", clCreateCommandQueue, &status, context_, device_.device,
                          CL_QUEUE_PROFILING_ENABLE);
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
    if (status != CL_SUCCESS) {
        RC_CL_RELEASE("context", clReleaseContext, context_);
        check_cl(status, "clCreateCommandQueue", device_.name);
    }
}

Context::~Context() {
    // Background builds nobody asked for: waited for, their programs (or errors) dropped.
    for (auto& [key, build] : pending_) {
        try {
            build.get();
        } catch (const std::exception&) {
            // Unused: its error concerns no kernel the work needed.
        }
    }
    programs_.clear();
    derived_.clear();  // their buffers released while the queue and context still stand
    if (queue_ != nullptr) {
        // No clFinish: every launch and transfer has been waited for, and releasing the queue
        // flushes it (a failure here could only be ignored).
        RC_CL_RELEASE("queue", clReleaseCommandQueue, queue_);
    }
    if (context_ != nullptr) {
        RC_CL_RELEASE("context", clReleaseContext, context_);
    }
}

std::unique_ptr<Program> Context::build(const std::string& entry,
                                        const std::string& options) const {
    // The BVH layout, and the device's compiler workarounds (device/compiler_workarounds.h).
    std::string defines = "-DRC_BVH_LAYOUT=" + std::to_string(static_cast<int>(bvh_layout_));
    if (const std::string workarounds = compiler_workaround_options(device_);
        !workarounds.empty()) {
        defines += " " + workarounds;
    }
    return std::make_unique<Program>(context_, device_, sources_, cache_, entry, defines, options,
                                     options_.dump_kernels_dir);
}

void Context::prebuild(const std::vector<ProgramRequest>& requests) {
    for (const ProgramRequest& request : requests) {
        prebuild_requests_.push_back(request);
        const std::string key = request.entry + "\n" + request.options;
        if (programs_.count(key) == 0 && pending_.count(key) == 0) {
            pending_.emplace(key, std::async(std::launch::async, [this, request] {
                                 return build(request.entry, request.options);
                             }));
        }
    }
}

const Program& Context::program(const std::string& entry, const std::string& options) {
    const std::string key = entry + "\n" + options;
    auto found = programs_.find(key);
    if (found == programs_.end()) {
        std::unique_ptr<Program> program;
        if (auto started = pending_.find(key); started != pending_.end()) {
            std::future<std::unique_ptr<Program>> background = std::move(started->second);
            pending_.erase(started);
            program = background.get();
        } else {
            program = build(entry, options);
        }
        builds_.push_back(program->report());
        found = programs_.emplace(key, std::move(program)).first;
    }
    return *found->second;
}

Kernel Context::kernel(const std::string& entry, const std::string& name,
                       const std::string& options) {
    return program(entry, options).kernel(name);
}

size_t Context::local_size_for(const Kernel& kernel) const {
    const size_t limit = kernel.max_work_group_size(device_.device);
    if (options_.local_size != 0) {
        if (options_.local_size > limit) {
            throw Error("work-group size " + std::to_string(options_.local_size) +
                            " exceeds the limit " + std::to_string(limit) + " of kernel " +
                            kernel.name() + " on " + device_.name,
                        kExitUsage);
        }
        return options_.local_size;
    }
    size_t local = std::min(kPreferredLocalSize, limit);
    // Largest power of two not above the limit.
    while ((local & (local - 1)) != 0) {
        local &= local - 1;
    }
    return std::max<size_t>(local, 1);
}

void Context::run_chunked(Kernel& kernel, size_t first, size_t end) {
    if (end <= first) {
        return;
    }
    if (end > std::numeric_limits<uint32_t>::max()) {
        throw Error("kernel " + kernel.name() + ": " + std::to_string(end) +
                    " work items exceed the 32-bit item range");
    }
    const size_t local = local_size_for(kernel);
    const size_t max_chunk = round_up(
        options_.max_chunk_items != 0 ? options_.max_chunk_items : kDefaultMaxChunkItems, local);
    const size_t first_chunk = std::min(max_chunk, round_up(kFirstChunkItems, local));
    size_t chunk = first_chunk;
    KernelTime& time = kernel_times_[kernel.name()];
    for (size_t begin = first; begin < end;) {
        const size_t items = std::min(chunk, end - begin);
        const cl_uint range[2] = {static_cast<cl_uint>(begin), static_cast<cl_uint>(begin + items)};
        kernel.set_arg(0, sizeof range[0], &range[0]);
        kernel.set_arg(1, sizeof range[1], &range[1]);
        const size_t global = round_up(items, local);
        cl_event event = nullptr;
        const auto enqueued = std::chrono::steady_clock::now();
        check_cl(RC_CL(clEnqueueNDRangeKernel, queue_, kernel.handle(), 1, nullptr, &global, &local,
                       0, nullptr, &event),
                 "clEnqueueNDRangeKernel", kernel.name());
        note_device_object("event", +1);
        const cl_int waited = RC_CL(clWaitForEvents, 1, &event);
        const double waited_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - enqueued).count();
        cl_ulong started = 0;
        cl_ulong ended = 0;
        cl_int profiled = RC_CL(clGetEventProfilingInfo, event, CL_PROFILING_COMMAND_START,
                                sizeof started, &started, nullptr);
        if (profiled == CL_SUCCESS) {
            profiled = RC_CL(clGetEventProfilingInfo, event, CL_PROFILING_COMMAND_END, sizeof ended,
                             &ended, nullptr);
        }
        RC_CL_RELEASE("event", clReleaseEvent, event);
        check_cl(waited, "clWaitForEvents", kernel.name());
        check_cl(profiled, "clGetEventProfilingInfo", kernel.name());
        // A device whose events do not measure (rusticl 22.3 gives every launch 1 ns): the
        // host's time from enqueue to completion instead, for the timings and the chunk sizes.
        double seconds = static_cast<double>(ended - started) * 1e-9;
        bool host_timed = false;
        if (seconds * kImplausibleProfileRatio < waited_seconds) {
            seconds = waited_seconds;
            time.host_timed += 1;
            host_timed = true;
        }
        time.seconds += seconds;
        time.launches += 1;
        time.items += items;
        begin += items;
        // Aim the next chunk at the target duration, within [local, max_chunk]. The host's time
        // holds the launch's own cost, which no chunk size removes (rusticl 22.3: about 0.06 s a
        // launch of ic_record_cells): there chunks stay at least the first one's size, or they
        // would shrink to a work group each and spend the render on launches.
        if (items == chunk && seconds > 0.0) {
            const double scale = std::clamp(options_.chunk_seconds / seconds, 0.25, 4.0);
            const size_t least = host_timed ? first_chunk : local;
            chunk =
                std::clamp(round_up(static_cast<size_t>(static_cast<double>(chunk) * scale), local),
                           least, max_chunk);
        }
    }
}

void Context::finish() { check_cl(RC_CL(clFinish, queue_), "clFinish", device_.name); }

}  // namespace rc
