// The options every device-using command shares (--device, kernel sources, chunking).
#pragma once

#include <vector>

#include "device/context.h"
#include "util/cli.h"

namespace rc {

std::vector<OptionSpec> device_option_specs();
ContextOptions context_options(const ParsedArguments& arguments);

}  // namespace rc
