#include "device/device_list.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <system_error>

#include "device/cl_calls.h"
#include "device/cl_error.h"
#include "util/error.h"
#include "util/text.h"

namespace rc {
namespace {

constexpr cl_int kPlatformNotFoundKhr = -1001;

std::string platform_string(cl_platform_id platform, cl_platform_info what) {
    size_t size = 0;
    check_cl(RC_CL(clGetPlatformInfo, platform, what, 0, nullptr, &size), "clGetPlatformInfo");
    std::string value(size, '\0');
    check_cl(RC_CL(clGetPlatformInfo, platform, what, size, value.data(), nullptr),
             "clGetPlatformInfo");
    value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
    return value;
}

std::string device_string(cl_device_id device, cl_device_info what) {
    size_t size = 0;
    check_cl(RC_CL(clGetDeviceInfo, device, what, 0, nullptr, &size), "clGetDeviceInfo");
    std::string value(size, '\0');
    check_cl(RC_CL(clGetDeviceInfo, device, what, size, value.data(), nullptr), "clGetDeviceInfo");
    value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
    return value;
}

template <class T>
T device_value(cl_device_id device, cl_device_info what) {
    T value{};
    check_cl(RC_CL(clGetDeviceInfo, device, what, sizeof value, &value, nullptr),
             "clGetDeviceInfo");
    return value;
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// The cache folder a driver would make under $XDG_CACHE_HOME, where that cannot be made: PoCL
// keeps its kernel cache there and its platform does not load without it (radcache then sees no
// platform at all). Empty when the variable is unset or its folder usable.
std::string unusable_cache_home() {
    const char* home = std::getenv("XDG_CACHE_HOME");
    if (home == nullptr || *home == '\0' || std::getenv("POCL_CACHE_DIR") != nullptr) {
        return "";
    }
    // The folder, or the nearest of its parents that exists, must be a writable folder (nothing
    // is created here).
    std::error_code error;
    std::filesystem::path folder = std::filesystem::absolute(home, error);
    while (!error && !std::filesystem::exists(folder, error) && folder.has_parent_path() &&
           folder.parent_path() != folder) {
        folder = folder.parent_path();
    }
    const bool usable =
        !error && std::filesystem::is_directory(folder, error) && access(folder.c_str(), W_OK) == 0;
    return usable ? "" : home;
}

std::string no_platform_message() {
    const std::string home = unusable_cache_home();
    if (!home.empty()) {
        return "no OpenCL platform found, and $XDG_CACHE_HOME (" + excerpt(home) +
               ") is not a writable folder: PoCL keeps its kernel cache there and does not "
               "load without it (set XDG_CACHE_HOME or POCL_CACHE_DIR to a writable folder)";
    }
    return "no OpenCL platform found: install an OpenCL driver, e.g. the Debian package "
           "pocl-opencl-icd (CPU) or your GPU vendor's OpenCL ICD";
}

}  // namespace

bool is_pocl(const DeviceInfo& device) {
    return device.platform_name.find("Portable Computing Language") != std::string::npos;
}

std::string DeviceInfo::spec() const {
    return std::to_string(platform_index) + ":" + std::to_string(device_index);
}

std::vector<DeviceInfo> list_devices() {
    cl_uint platform_count = 0;
    const cl_int status = RC_CL(clGetPlatformIDs, 0, nullptr, &platform_count);
    if (status == kPlatformNotFoundKhr || (status == CL_SUCCESS && platform_count == 0)) {
        throw Error(no_platform_message(), kExitUsage);
    }
    check_cl(status, "clGetPlatformIDs");
    std::vector<cl_platform_id> platforms(platform_count);
    check_cl(RC_CL(clGetPlatformIDs, platform_count, platforms.data(), nullptr),
             "clGetPlatformIDs");

    std::vector<DeviceInfo> devices;
    for (cl_uint p = 0; p < platform_count; ++p) {
        cl_uint device_count = 0;
        const cl_int found =
            RC_CL(clGetDeviceIDs, platforms[p], CL_DEVICE_TYPE_ALL, 0, nullptr, &device_count);
        if (found == CL_DEVICE_NOT_FOUND) {
            continue;
        }
        check_cl(found, "clGetDeviceIDs");
        std::vector<cl_device_id> ids(device_count);
        check_cl(RC_CL(clGetDeviceIDs, platforms[p], CL_DEVICE_TYPE_ALL, device_count, ids.data(),
                       nullptr),
                 "clGetDeviceIDs");
        for (cl_uint d = 0; d < device_count; ++d) {
            DeviceInfo info;
            info.platform_index = static_cast<int>(p);
            info.device_index = static_cast<int>(d);
            info.platform = platforms[p];
            info.device = ids[d];
            info.platform_name = platform_string(platforms[p], CL_PLATFORM_NAME);
            info.platform_version = platform_string(platforms[p], CL_PLATFORM_VERSION);
            info.name = device_string(ids[d], CL_DEVICE_NAME);
            info.vendor = device_string(ids[d], CL_DEVICE_VENDOR);
            const auto type = device_value<cl_device_type>(ids[d], CL_DEVICE_TYPE);
            info.is_gpu = (type & CL_DEVICE_TYPE_GPU) != 0;
            info.is_cpu = (type & CL_DEVICE_TYPE_CPU) != 0;
            info.type = info.is_gpu                                ? "GPU"
                        : info.is_cpu                              ? "CPU"
                        : (type & CL_DEVICE_TYPE_ACCELERATOR) != 0 ? "accelerator"
                                                                   : "other";
            info.compute_units = device_value<cl_uint>(ids[d], CL_DEVICE_MAX_COMPUTE_UNITS);
            info.global_memory = device_value<cl_ulong>(ids[d], CL_DEVICE_GLOBAL_MEM_SIZE);
            info.max_allocation = device_value<cl_ulong>(ids[d], CL_DEVICE_MAX_MEM_ALLOC_SIZE);
            info.max_work_group_size = device_value<size_t>(ids[d], CL_DEVICE_MAX_WORK_GROUP_SIZE);
            info.opencl_c_version = device_string(ids[d], CL_DEVICE_OPENCL_C_VERSION);
            info.driver_version = device_string(ids[d], CL_DRIVER_VERSION);
            const std::string extensions = device_string(ids[d], CL_DEVICE_EXTENSIONS);
            info.has_fp64 = extensions.find("cl_khr_fp64") != std::string::npos;
            devices.push_back(std::move(info));
        }
    }
    if (devices.empty()) {
        throw Error(no_platform_message(), kExitUsage);
    }
    return devices;
}

std::string format_device_table(const std::vector<DeviceInfo>& devices) {
    std::vector<std::vector<std::string>> rows = {
        {"index", "platform", "device", "type", "units", "memory", "OpenCL C"}};
    for (const DeviceInfo& device : devices) {
        char memory[32];
        std::snprintf(memory, sizeof memory, "%.1f GiB",
                      static_cast<double>(device.global_memory) / (1024.0 * 1024.0 * 1024.0));
        rows.push_back({device.spec(), device.platform_name, device.name, device.type,
                        std::to_string(device.compute_units), memory, device.opencl_c_version});
    }
    std::vector<size_t> widths(rows[0].size(), 0);
    for (const auto& row : rows) {
        for (size_t c = 0; c < row.size(); ++c) {
            widths[c] = std::max(widths[c], row[c].size());
        }
    }
    std::string table;
    for (const auto& row : rows) {
        std::string line;
        for (size_t c = 0; c < row.size(); ++c) {
            line += row[c];
            if (c + 1 < row.size()) {
                line += std::string(widths[c] - row[c].size() + 2, ' ');
            }
        }
        table += line + "\n";
    }
    return table;
}

DeviceInfo select_device(const std::vector<DeviceInfo>& devices, const std::string& spec_option) {
    std::string spec = spec_option;
    std::string source = "--device";
    if (spec.empty()) {
        if (const char* env = std::getenv("RADCACHE_DEVICE"); env != nullptr && *env != '\0') {
            spec = env;
            source = "RADCACHE_DEVICE";
        }
    }
    if (spec.empty()) {
        for (const DeviceInfo& device : devices) {
            if (device.is_gpu) {
                return device;
            }
        }
        for (const DeviceInfo& device : devices) {
            if (device.is_cpu) {
                return device;
            }
        }
        return devices.front();
    }
    if (lower(spec) == "all" || spec.find(',') != std::string::npos) {
        throw Error(source + " '" + spec +
                        "' names several devices; this command uses one (radcache render takes "
                        "several)",
                    kExitUsage);
    }
    // At most 9 digits each (an index past int names no device rather than overflowing).
    static const std::regex index_form(R"(^\s*(\d{1,9})\s*:\s*(\d{1,9})\s*$)");
    std::smatch match;
    if (std::regex_match(spec, match, index_form)) {
        const int platform = std::stoi(match[1].str());
        const int device = std::stoi(match[2].str());
        for (const DeviceInfo& info : devices) {
            if (info.platform_index == platform && info.device_index == device) {
                return info;
            }
        }
    } else {
        // Part of the platform's name or the device's: "Intel(R) OpenCL" names Intel's CPU
        // runtime where PoCL's device bears the same processor name.
        const std::string needle = lower(spec);
        for (const DeviceInfo& info : devices) {
            if (lower(info.platform_name + " " + info.name).find(needle) != std::string::npos) {
                return info;
            }
        }
    }
    // One line: the devices by index and name (`radcache devices` gives the table).
    std::string listed;
    for (const DeviceInfo& info : devices) {
        listed += (listed.empty() ? "" : ", ") + info.spec() + " " + info.name;
    }
    throw Error("no OpenCL device matches " + source + " '" + excerpt(spec) +
                    "' (devices: " + listed + "; `radcache devices` lists them)",
                kExitUsage);
}

std::vector<DeviceInfo> select_devices(const std::vector<DeviceInfo>& devices,
                                       const std::string& spec) {
    if (lower(spec) == "all") {
        return devices;
    }
    if (spec.find(',') == std::string::npos) {
        return {select_device(devices, spec)};
    }
    std::vector<DeviceInfo> chosen;
    size_t start = 0;
    while (start <= spec.size()) {
        const size_t comma = std::min(spec.find(',', start), spec.size());
        const std::string entry = spec.substr(start, comma - start);
        if (entry.find_first_not_of(" \t") == std::string::npos) {
            throw Error("--device '" + spec + "' has an empty entry", kExitUsage);
        }
        const DeviceInfo device = select_device(devices, entry);
        for (const DeviceInfo& other : chosen) {
            if (other.spec() == device.spec()) {
                throw Error("--device '" + spec + "' names device " + device.spec() + " (" +
                                device.name + ") twice",
                            kExitUsage);
            }
        }
        chosen.push_back(device);
        start = comma + 1;
    }
    return chosen;
}

}  // namespace rc
