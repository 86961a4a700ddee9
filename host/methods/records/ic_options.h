// Irradiance caching's command-line options (`--method ic`, and the diffuse records of
// `--method rc` and `--method sdrc`): their table over IrradianceCacheOptions.
#pragma once

#include "methods/method.h"
#include "methods/records/irradiance_cache.h"

namespace rc {

// --accuracy, --ic-*, --cache-in/--cache-out and --light-samples: the irradiance records'
// options every method with irradiance records takes.
OptionTable<IrradianceCacheOptions> irradiance_record_option_table();

// IrradianceCacheOptions as the command line's defaults have them (--light-samples).
IrradianceCacheOptions irradiance_record_defaults();

// Error (exit status 2) naming the option: --cache-out's folder must be writable.
void finish_irradiance_record_options(const IrradianceCacheOptions& options);

// The options with the shared settings applied (and the `records` layer drawn when it is
// written); Error (exit status 2) for cache files with several frames.
IrradianceCacheOptions irradiance_record_options(IrradianceCacheOptions options,
                                                 const MethodSettings& settings);

}  // namespace rc
