#include <iostream>

#include "app/commands.h"
#include "device/device_list.h"
#include "util/cli.h"
#include "util/error.h"

namespace rc {

int run_devices_command(const std::vector<std::string>& args) {
    const ParsedArguments arguments = parse_arguments("radcache devices", args, {});
    if (arguments.has("--help")) {
        std::cout << format_help("radcache devices",
                                 "Lists every OpenCL platform and device; the index P:D selects "
                                 "one with --device.",
                                 {});
        return 0;
    }
    if (!arguments.positionals().empty()) {
        throw Error("radcache devices takes no arguments", kExitUsage);
    }
    std::cout << format_device_table(list_devices());
    return 0;
}

}  // namespace rc
