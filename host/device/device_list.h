// The OpenCL platforms and devices of this machine, and choosing one by a user's spec.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

struct _cl_platform_id;
struct _cl_device_id;

namespace rc {

struct DeviceInfo {
    int platform_index = 0;
    int device_index = 0;
    std::string platform_name;
    std::string platform_version;
    std::string name;
    std::string vendor;
    std::string type;  // "GPU", "CPU", "accelerator" or "other"
    bool is_gpu = false;
    bool is_cpu = false;
    unsigned compute_units = 0;
    uint64_t global_memory = 0;
    uint64_t max_allocation = 0;
    size_t max_work_group_size = 0;
    std::string opencl_c_version;
    std::string driver_version;
    bool has_fp64 = false;
    _cl_platform_id* platform = nullptr;
    _cl_device_id* device = nullptr;

    // "P:D", the index form of --device.
    std::string spec() const;
};

// Every device of every platform. Throws Error (exit status 2) naming the package that provides
// a platform (pocl-opencl-icd) when there is none.
// Whether `device` is PoCL's (its platform "Portable Computing Language").
bool is_pocl(const DeviceInfo& device);

std::vector<DeviceInfo> list_devices();

// The table `radcache devices` prints: index, platform, device, type, compute units, global
// memory and OpenCL C version, one device per line under a header.
std::string format_device_table(const std::vector<DeviceInfo>& devices);

// The device a spec names: "P:D", or a case-insensitive substring of the device name (the first
// match). An empty spec takes $RADCACHE_DEVICE, and without it the first GPU, else the first CPU,
// else the first device. An unknown spec throws Error (exit status 2) whose message lists the
// devices.
DeviceInfo select_device(const std::vector<DeviceInfo>& devices, const std::string& spec);

// The devices a --device value names for one render on several devices: "all" (every device,
// in list order), or specs separated by commas (each as select_device takes it); a single spec
// names one device. Error (exit status 2) for an empty entry or a device named twice.
std::vector<DeviceInfo> select_devices(const std::vector<DeviceInfo>& devices,
                                       const std::string& spec);

}  // namespace rc
