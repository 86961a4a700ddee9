#include <iostream>

#include "app/commands.h"
#include "device/device_list.h"
#include "util/error.h"

namespace rc {
namespace {

int devices(const ParsedArguments& arguments) {
    if (!arguments.positionals().empty()) {
        throw Error("radcache devices takes no arguments", kExitUsage);
    }
    std::cout << format_device_table(list_devices());
    return 0;
}

}  // namespace

CommandSpec devices_command() {
    return {.name = "devices",
            .summary = "list the OpenCL platforms and devices",
            .description =
                "Lists every OpenCL platform and device; the index P:D selects one "
                "with --device.",
            .run = devices};
}

}  // namespace rc
