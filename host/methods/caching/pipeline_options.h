// Irradiance caching's command-line options (`--method ic`, and the diffuse records of
// `--method rc` and `--method sdrc`): their table over PipelineSettings.
#pragma once

#include "methods/caching/cache_pipeline.h"
#include "methods/method.h"

namespace rc {

// --accuracy, --ic-*, --cache-in/--cache-out and --light-samples: the irradiance records'
// options every method with irradiance records takes.
OptionTable<PipelineSettings> pipeline_option_table();

// PipelineSettings as the command line's defaults have them (--light-samples).
PipelineSettings pipeline_defaults();

// Error (exit status 2) naming the option: --cache-out's folder must be writable.
void finish_pipeline_settings(const PipelineSettings& options);

// The options with the shared settings applied (and the `records` layer drawn when it is
// written); Error (exit status 2) for cache files with several frames.
PipelineSettings pipeline_settings(PipelineSettings options, const MethodSettings& settings);

}  // namespace rc
