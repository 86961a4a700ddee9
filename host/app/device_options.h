// The options every device-using command shares (--device, kernel sources, chunking).
#pragma once

#include <vector>

#include "device/context.h"
#include "util/cli.h"

namespace rc {

std::vector<OptionSpec> device_option_specs();
// `specs` (a command's own options) followed by the device options.
std::vector<OptionSpec> with_device_options(std::vector<OptionSpec> specs);
ContextOptions context_options(const ParsedArguments& arguments);

}  // namespace rc
