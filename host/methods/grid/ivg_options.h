// The irradiance vector grid's options (--method ivg, ivg-gather, and ic with --ic-ivg), building
// a frame's grid from them, and its statistics as JSON.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "methods/grid/irradiance_vector_grid.h"
#include "methods/method.h"
#include "util/cli.h"

namespace rc {

// The options of the grid itself (resolution, photons, interpolation, layout, files).
OptionTable<IvgOptions> ivg_option_table();

// Error (exit status 2) for the first grid option given: `why` says when they apply.
void refuse_ivg_options(const ParsedArguments& arguments, const std::string& why);

// Error (exit status 2) naming the option: --grid-out's folder must be writable, --grid-in
// excludes --photons.
void finish_ivg_options(const IvgOptions& options, const ParsedArguments& arguments);

// The grid's options with the shared settings applied; Error (exit status 2) for --grid-in or
// --grid-out with several frames.
IvgOptions ivg_options(IvgOptions options, const MethodSettings& settings);

// The frame's grid: photons traced (or the grid loaded), normalised, saved when asked; its
// statistics go to result->stats["grid"] and its rays to result->rays.
std::unique_ptr<IrradianceVectorGrid> build_frame_grid(const FrameScene& frame,
                                                       const IvgOptions& options,
                                                       const FrameHooks& hooks,
                                                       FrameResult* result);

nlohmann::json ivg_stats_json(const IvgStats& stats);

}  // namespace rc
