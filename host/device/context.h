// One OpenCL device in use: its context and profiling queue, its programs (built once), and the
// one kernel-launch function (DESIGN.md §3) with per-kernel timing and chunking.
#pragma once

#include <cstdint>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "device/binary_cache.h"
#include "device/buffer.h"
#include "device/bvh_layout.h"
#include "device/device_list.h"
#include "device/kernel.h"
#include "device/kernel_sources.h"
#include "device/program.h"

struct _cl_context;
struct _cl_command_queue;

namespace rc {

struct ContextOptions {
    std::string device_spec;           // --device; empty: $RADCACHE_DEVICE, then default
    std::filesystem::path kernel_dir;  // override for the embedded kernel sources
    std::filesystem::path cache_dir = BinaryCache::default_directory();  // empty: no cache
    std::filesystem::path dump_kernels_dir;  // where to write expanded sources, if anywhere
    size_t local_size = 0;                   // work-group size; 0: chosen per kernel
    size_t max_chunk_items = 0;              // largest launch; 0: the default (2^20)
    double chunk_seconds = 0.1;              // launches aim at this duration
    uint64_t memory_limit = 0;  // most bytes held in buffers at once; 0: the global memory
    std::optional<BvhLayout> bvh_layout;  // --bvh; none: default_bvh_layout()
    bool allow_loop_cap =
        false;  // --allow-loop-cap: render where loops end early (device_features.h)
};

// Device memory held in this context's buffers (DeviceBuffer), in bytes: now, and the most since
// the last reset_peak_memory(). Buffers share it with their context, so that one outliving the
// context (a method's, destroyed after it) still gives back its bytes.
struct DeviceMemory {
    size_t in_use = 0;
    size_t peak = 0;

    void allocate(size_t bytes) {
        in_use += bytes;
        peak = in_use > peak ? in_use : peak;
    }
    void release(size_t bytes) { in_use -= bytes < in_use ? bytes : in_use; }
};

// Accumulated device time of one kernel (from profiling events).
struct KernelTime {
    double seconds = 0.0;
    size_t launches = 0;
    size_t items = 0;
    size_t host_timed = 0;  // launches whose events did not measure: the host's time instead
};

class Context {
   public:
    explicit Context(const ContextOptions& options = {});
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    const DeviceInfo& device() const { return device_; }
    const ContextOptions& options() const { return options_; }
    // The most bytes this run may hold in buffers: --device-memory, else the device's global
    // memory (0: unknown, no limit); and what sets it ("--device-memory" or the device's name).
    uint64_t memory_limit() const {
        return options_.memory_limit != 0 ? options_.memory_limit : device_.global_memory;
    }
    std::string memory_limit_source() const {
        return options_.memory_limit != 0 ? "--device-memory" : device_.name;
    }
    // The BVH layout every program's traversal is built for (device/bvh_layout.h).
    BvhLayout bvh_layout() const { return bvh_layout_; }

    // The program built from `entry` (relative to kernels/) with -D `options` and the BVH
    // layout's -DRC_BVH_LAYOUT, built once (waiting for its background build when prebuild()
    // started one; a failed build throws here).
    const Program& program(const std::string& entry, const std::string& options = "");
    // Starts building every requested program not built or started yet, each on its own thread,
    // all at once (a cold render does not build its programs one after another; a
    // driver's compiler runs them side by side). program() collects them.
    void prebuild(const std::vector<ProgramRequest>& requests);
    Kernel kernel(const std::string& entry, const std::string& name,
                  const std::string& options = "");
    const std::vector<ProgramBuildReport>& program_builds() const { return builds_; }
    // Every program prebuild() was asked for, in the order asked.
    const std::vector<ProgramRequest>& prebuild_requests() const { return prebuild_requests_; }

    // Runs `kernel` over items [0, count). The kernel's first two parameters are
    // (uint begin, uint end) and it handles item begin + get_global_id(0) when below end; the
    // remaining parameters are `args` (buffers, plain values, or argument groups). Large
    // launches are split into chunks of bounded duration; an item's result never depends on the
    // chunking.
    template <class... Args>
    void launch(Kernel& kernel, size_t count, const Args&... args) {
        launch_range(kernel, 0, count, args...);
    }
    // The same over items [first, end) (a share of a larger item range: several devices).
    template <class... Args>
    void launch_range(Kernel& kernel, size_t first, size_t end, const Args&... args) {
        unsigned index = 2;
        (set_kernel_arg(kernel, index, args), ...);
        run_chunked(kernel, first, end);
    }

    const std::map<std::string, KernelTime>& kernel_times() const { return kernel_times_; }

    // The buffers' bookkeeping (DeviceBuffer keeps a share) and its figures for --stats.
    const std::shared_ptr<DeviceMemory>& memory_counter() const { return memory_; }
    const DeviceMemory& device_memory() const { return *memory_; }
    void reset_peak_memory() { memory_->peak = memory_->in_use; }
    void reset_kernel_times() { kernel_times_.clear(); }

    // The work-group size launches of `kernel` use.
    size_t local_size_for(const Kernel& kernel) const;

    void finish();

    // Device data derived from the scene once and reused by every later render on this context
    // (radiance caching's BRDF tables: the next frame, or --method auto's render after its
    // pilot): the entry under `key`, made by `make` on the first call. Released with the context.
    template <class T, class Make>
    std::shared_ptr<const T> derived(const std::string& key, Make&& make) {
        auto found = derived_.find(key);
        if (found == derived_.end()) {
            std::shared_ptr<const T> made = make();
            found = derived_.emplace(key, std::move(made)).first;
        }
        return std::static_pointer_cast<const T>(found->second);
    }

    _cl_context* cl_context() const { return context_; }
    _cl_command_queue* cl_queue() const { return queue_; }

   private:
    // Builds (or loads from the binary cache) one program; safe on any thread.
    std::unique_ptr<Program> build(const std::string& entry, const std::string& options) const;
    static void set_kernel_arg(Kernel& kernel, unsigned& index, const DeviceBuffer& buffer) {
        _cl_mem* handle = buffer.handle();
        kernel.set_arg(index++, sizeof handle, &handle);
    }
    static void set_kernel_arg(Kernel& kernel, unsigned& index, const KernelArgumentGroup& group) {
        index += group.set_kernel_args(kernel, index);
    }
    // A plain value (the kernel parameter must have the same size).
    template <class T>
    static constexpr bool kPlainArgument =
        std::is_trivially_copyable_v<T> && !std::is_base_of_v<DeviceBuffer, T> &&
        !std::is_base_of_v<KernelArgumentGroup, T>;
    template <class T>
    static std::enable_if_t<kPlainArgument<T>> set_kernel_arg(Kernel& kernel, unsigned& index,
                                                              const T& value) {
        kernel.set_arg(index++, sizeof(T), &value);
    }
    void run_chunked(Kernel& kernel, size_t first, size_t end);

    ContextOptions options_;
    DeviceInfo device_;
    BvhLayout bvh_layout_;
    KernelSources sources_;
    BinaryCache cache_;
    _cl_context* context_ = nullptr;
    _cl_command_queue* queue_ = nullptr;
    std::map<std::string, std::unique_ptr<Program>> programs_;
    std::map<std::string, std::future<std::unique_ptr<Program>>> pending_;  // prebuild()'s
    std::vector<ProgramRequest> prebuild_requests_;
    std::vector<ProgramBuildReport> builds_;
    std::map<std::string, KernelTime> kernel_times_;
    std::map<std::string, std::shared_ptr<const void>> derived_;  // derived()'s
    std::shared_ptr<DeviceMemory> memory_ = std::make_shared<DeviceMemory>();
};

}  // namespace rc
