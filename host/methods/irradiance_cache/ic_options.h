// Irradiance caching's command-line options (`--method ic`, and the diffuse records of
// `--method rc`): their specs and their parsing into IrradianceCacheOptions.
#pragma once

#include <vector>

#include "methods/irradiance_cache/irradiance_cache.h"
#include "methods/method.h"

namespace rc {

// --accuracy, --ic-*, --cache-in/--cache-out, --light-samples and the grid's options.
std::vector<OptionSpec> irradiance_cache_option_specs();

// Reads and validates them (Error with exit status 2 naming the option); the shared settings
// applied.
IrradianceCacheOptions parse_irradiance_cache_options(const ParsedArguments& arguments,
                                                      const MethodSettings& settings);

}  // namespace rc
