#include "device/program.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <optional>

#include "device/build_log.h"
#include "device/cl_calls.h"
#include "device/cl_error.h"
#include "device/device_list.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"
#include "util/stderr_capture.h"

namespace rc {
namespace {

// OpenCL C 1.2 everywhere; no vendor flags and no -cl-fast-relaxed-math (DESIGN.md §3).
constexpr const char* kBaseOptions = "-cl-std=CL1.2";

std::string build_log(cl_program program, cl_device_id device) {
    size_t size = 0;
    if (RC_CL(clGetProgramBuildInfo, program, device, CL_PROGRAM_BUILD_LOG, 0, nullptr, &size) !=
        CL_SUCCESS) {
        return "";  // no log: the error line says only what failed
    }
    std::string log(size, '\0');
    if (RC_CL(clGetProgramBuildInfo, program, device, CL_PROGRAM_BUILD_LOG, size, log.data(),
              nullptr) != CL_SUCCESS) {
        return "";  // no log: the error line says only what failed
    }
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) {
        log.pop_back();
    }
    return log;
}

// What follows a failed build's error: the driver's build log, then what its compiler printed on
// stderr meanwhile; without a log (it could not be read), the compiler's lines on the error's
// own line.
std::string build_failure_details(const std::string& log, const std::string& compiler) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < compiler.size()) {
        const size_t end = std::min(compiler.find('\n', start), compiler.size());
        if (end > start) {
            lines.push_back(compiler.substr(start, end - start));
        }
        start = end + 1;
    }
    std::string details = log.empty() ? "" : "; build log:\n" + log;
    for (size_t i = 0; i < lines.size(); ++i) {
        details +=
            log.empty() ? (i == 0 ? "; compiler output: " : "; ") + lines[i] : "\n" + lines[i];
    }
    return details;
}

// Builds from a binary; nullptr when the driver refuses it (treated like a corrupt entry).
cl_program try_build_from_binary(cl_context context, cl_device_id device,
                                 const std::vector<unsigned char>& binary,
                                 const std::string& options) {
    const size_t size = binary.size();
    const unsigned char* data = binary.data();
    cl_int binary_status = CL_SUCCESS;
    cl_int status = CL_SUCCESS;
    cl_program program = RC_CL_CREATE("program", clCreateProgramWithBinary, &status, context, 1,
                                      &device, &size, &data, &binary_status);
    if (status != CL_SUCCESS || binary_status != CL_SUCCESS) {
        if (program != nullptr) {
            RC_CL_RELEASE("program", clReleaseProgram, program);
        }
        return nullptr;
    }
    if (RC_CL(clBuildProgram, program, 1, &device, options.c_str(), nullptr, nullptr) !=
        CL_SUCCESS) {
        RC_CL_RELEASE("program", clReleaseProgram, program);
        return nullptr;
    }
    return program;
}

std::vector<unsigned char> program_binary(cl_program program, const std::string& entry) {
    size_t size = 0;
    check_cl(RC_CL(clGetProgramInfo, program, CL_PROGRAM_BINARY_SIZES, sizeof size, &size, nullptr),
             "clGetProgramInfo", entry);
    std::vector<unsigned char> binary(size);
    unsigned char* data = binary.data();
    check_cl(RC_CL(clGetProgramInfo, program, CL_PROGRAM_BINARIES, sizeof data, &data, nullptr),
             "clGetProgramInfo", entry);
    return binary;
}

}  // namespace

Program::Program(_cl_context* context, const DeviceInfo& device, const KernelSources& sources,
                 const BinaryCache& cache, const std::string& entry,
                 const std::string& context_defines, const std::string& options,
                 const std::filesystem::path& dump_dir)
    : entry_(entry) {
    const auto start = std::chrono::steady_clock::now();
    report_.entry = entry;
    report_.options = options;
    const std::string source = sources.expand(entry);
    const std::string all_options =
        std::string(kBaseOptions) + " " + context_defines + (options.empty() ? "" : " " + options);
    if (!dump_dir.empty()) {
        // One file per entry and options: "dir/entry.cl" built with "-DX=1" is dir_entry.DX_1.cl.
        std::string flat = entry;
        for (char& c : flat) {
            c = (c == '/') ? '_' : c;
        }
        if (!options.empty()) {
            std::string tag = ".";
            for (char c : options) {
                tag += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
            }
            const size_t dot = flat.rfind('.');
            flat.insert(dot == std::string::npos ? flat.size() : dot, tag);
        }
        std::filesystem::create_directories(dump_dir);
        write_file_atomically(dump_dir / flat, "// build options: " + all_options + "\n" + source,
                              WriteTiming::kNow);
    }

    const BinaryCacheKey key =
        BinaryCacheKey::of(source, all_options, device.name, device.driver_version);
    std::vector<unsigned char> binary;
    const CacheLookup lookup = cache.load(key, binary);
    if (lookup == CacheLookup::kHit) {
        handle_ = try_build_from_binary(context, device.device, binary, all_options);
        report_.from_cache = handle_ != nullptr;
        report_.replaced_corrupt_entry = handle_ == nullptr;
    } else if (lookup == CacheLookup::kCorrupt) {
        report_.replaced_corrupt_entry = true;
    }
    if (report_.replaced_corrupt_entry) {
        log_warning("ignoring corrupt kernel cache entry " + cache.entry_path(key).string() +
                    "; rebuilding " + entry);
    }

    if (handle_ == nullptr) {
        const char* text = source.c_str();
        const size_t length = source.size();
        cl_int status = CL_SUCCESS;
        handle_ =
            RC_CL_CREATE("program", clCreateProgramWithSource, &status, context, 1, &text, &length);
        check_cl(status, "clCreateProgramWithSource", entry);
        // PoCL's compiler prints its own summary ("2 errors generated.") on stderr: taken into
        // the error's build log, so that the error is all the user sees. (Only on PoCL: the
        // capture holds the process's stderr, so builds on several threads take turns there.)
        std::optional<StderrCapture> compiler_output;
        if (is_pocl(device)) {
            compiler_output.emplace();
        }
        status = RC_CL(clBuildProgram, handle_, 1, &device.device, all_options.c_str(), nullptr,
                       nullptr);
        const std::string chatter = compiler_output ? compiler_output->finish_text() : "";
        if (status == CL_SUCCESS && !chatter.empty()) {
            std::fputs(chatter.c_str(), stderr);  // a successful build's warnings, as they were
        }
        if (status != CL_SUCCESS) {
            const std::string details = build_failure_details(
                map_build_log(build_log(handle_, device.device), source), chatter);
            RC_CL_RELEASE("program", clReleaseProgram, handle_);
            handle_ = nullptr;
            throw Error("clBuildProgram(" + entry + ") failed: " + cl_error_name(status) + " on " +
                        device.name + details);
        }
        try {
            cache.store(key, program_binary(handle_, entry));
        } catch (...) {
            RC_CL_RELEASE("program", clReleaseProgram, handle_);  // the destructor will not run
            handle_ = nullptr;
            throw;
        }
    }
    report_.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Program::~Program() {
    if (handle_ != nullptr) {
        RC_CL_RELEASE("program", clReleaseProgram, handle_);
    }
}

Kernel Program::kernel(const std::string& name) const {
    cl_int status = CL_SUCCESS;
    cl_kernel handle = RC_CL_CREATE("kernel", clCreateKernel, &status, handle_, name.c_str());
    check_cl(status, "clCreateKernel", name + " in " + entry_);
    return Kernel(handle, name);
}

}  // namespace rc
