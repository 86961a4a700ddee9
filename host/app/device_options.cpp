#include "app/device_options.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "util/error.h"
#include "util/text.h"

namespace rc {

std::vector<OptionSpec> device_option_specs() {
    return {
        {"--device", "", "SPEC",
         "OpenCL device: P:D or part of its platform and device name (default: $RADCACHE_DEVICE, "
         "else the first GPU, else the first CPU)"},
        {"--kernel-dir", "", "DIR",
         "read kernel sources from DIR instead of the embedded copies ($RADCACHE_KERNEL_DIR)"},
        {"--dump-kernels", "", "DIR", "write the expanded kernel sources to DIR"},
        {"--no-kernel-cache", "", "", "do not read or write the kernel binary cache"},
        OptionSpec{"--local-size", "", "N", "work-group size of every launch (default: per kernel)"}
            .integers(1, 1024),
        OptionSpec{"--max-chunk", "", "N",
                   "largest number of work items in one launch (default 2^20)"}
            .integers(1, 1LL << 31),
        OptionSpec{"--device-memory", "", "MIB",
                   "the most device memory a run may hold in buffers (default: the device's "
                   "global memory); a run that needs more is refused with the figure"}
            .integers(1, 1LL << 40),
        {"--allow-loop-cap", "", "",
         "render on a device that ends a work item's loops early (Mesa's llvmpipe, after 65535 "
         "iterations; refused otherwise): kernels that loop longer give wrong images "
         "($RADCACHE_ALLOW_LOOP_CAP=1 does the same)"},
        {"--bvh", "", "LAYOUT",
         "BVH layout the traversal uses: wide (8-wide, compressed; the default) or bvh4 (4-wide, "
         "float boxes); docs/bvh.md"},
    };
}

std::vector<OptionSpec> with_device_options(std::vector<OptionSpec> specs) {
    for (OptionSpec& spec : device_option_specs()) {
        specs.push_back(std::move(spec));
    }
    return specs;
}

ContextOptions context_options(const ParsedArguments& arguments) {
    ContextOptions options;
    options.device_spec = arguments.value("--device");
    options.kernel_dir = arguments.value("--kernel-dir");
    options.dump_kernels_dir = arguments.value("--dump-kernels");
    if (!options.dump_kernels_dir.empty()) {
        // The folder made (or found) before any work: one line naming it where it cannot be.
        std::error_code error;
        std::filesystem::create_directories(options.dump_kernels_dir, error);
        if (error || !std::filesystem::is_directory(options.dump_kernels_dir)) {
            throw Error("--dump-kernels " + excerpt(options.dump_kernels_dir.string()) +
                            ": cannot make the folder (" +
                            (error ? error.message() : std::string("not a folder")) + ")",
                        kExitUsage);
        }
    }
    if (arguments.has("--no-kernel-cache")) {
        options.cache_dir.clear();
    }
    options.local_size = static_cast<size_t>(arguments.integer("--local-size", 0));
    options.max_chunk_items = static_cast<size_t>(arguments.integer("--max-chunk", 0));
    options.memory_limit = static_cast<uint64_t>(arguments.integer("--device-memory", 0)) << 20;
    const char* allow_loop_cap = std::getenv("RADCACHE_ALLOW_LOOP_CAP");
    options.allow_loop_cap = arguments.has("--allow-loop-cap") ||
                             (allow_loop_cap != nullptr && std::string(allow_loop_cap) == "1");
    if (arguments.has("--bvh")) {
        const std::string name = arguments.value("--bvh");
        options.bvh_layout = parse_bvh_layout(name);
        if (!options.bvh_layout) {
            throw Error("--bvh: unknown BVH layout '" + name + "' (bvh4 or wide)", kExitUsage);
        }
    }
    return options;
}

}  // namespace rc
