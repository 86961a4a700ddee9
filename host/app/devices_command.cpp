#include <iostream>

#include "app/commands.h"
#include "device/compiler_workarounds.h"
#include "device/context.h"
#include "device/device_features.h"
#include "device/device_list.h"
#include "util/error.h"

namespace rc {
namespace {

// One line per device: what it lacks that the kernels would use (device_features.h), from a
// probe on the device (its programs cached like any other).
void print_lacks(const std::vector<DeviceInfo>& devices) {
    std::cout << "\nwhat each device lacks that radcache's kernels would use:\n";
    for (const DeviceInfo& device : devices) {
        std::string line = "nothing";
        try {
            ContextOptions options;
            options.device_spec = device.spec();
            Context context(options);
            const std::vector<std::string> lacks = lacking(probe_device_features(context));
            if (!lacks.empty()) {
                line.clear();
                for (const std::string& lack : lacks) {
                    line += (line.empty() ? "" : "; ") + lack;
                }
            }
        } catch (const Error& error) {
            line = std::string("not probed: ") + error.what();
        }
        std::cout << device.spec() << "    " << line << "\n";
    }
}

// The compiler workarounds a device's programs are built with (device/compiler_workarounds.h),
// one line each; nothing where no device needs one.
void print_workarounds(const std::vector<DeviceInfo>& devices) {
    bool header = false;
    for (const DeviceInfo& device : devices) {
        for (const CompilerWorkaround& workaround : compiler_workarounds(device)) {
            if (!header) {
                std::cout << "\ncompiler workarounds (docs/devices.md):\n";
                header = true;
            }
            std::cout << device.spec() << "    " << workaround.reason << "\n";
        }
    }
}

int devices(const ParsedArguments& arguments) {
    if (!arguments.positionals().empty()) {
        throw Error("radcache devices takes no arguments", kExitUsage);
    }
    const std::vector<DeviceInfo> devices = list_devices();
    std::cout << format_device_table(devices);
    print_lacks(devices);
    print_workarounds(devices);
    return 0;
}

}  // namespace

CommandSpec devices_command() {
    return {.name = "devices",
            .summary = "list the OpenCL platforms and devices, and what each lacks",
            .description =
                "Lists every OpenCL platform and device; the index P:D selects one "
                "with --device. Then, per device, what it lacks that radcache's kernels "
                "would use (an extension its compiler does not define, profiling events "
                "that do not measure) and what radcache does without it; last, the compiler "
                "workarounds a device's programs are built with.",
            .run = devices};
}

}  // namespace rc
