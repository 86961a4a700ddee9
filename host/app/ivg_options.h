// The irradiance vector grid's `radcache render` options (--method ivg, ivg-gather, and ic with
// --ic-ivg) and its statistics as JSON.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/cli.h"
#include "methods/irradiance_vector_grid/irradiance_vector_grid.h"

namespace rc {

std::vector<OptionSpec> ivg_option_specs();

// Whether `method` (with the --ic-ivg flag for ic) builds a grid.
bool uses_grid(const std::string& method, const ParsedArguments& arguments);

// The grid's options from the command line; Error (exit status 2) naming the option for a bad
// value, or for a grid option given to a method that builds no grid.
IvgOptions ivg_options(const ParsedArguments& arguments, const std::string& method);

// --gather-rays (ivg-gather only; default kDefaultGatherRays).
int gather_rays(const ParsedArguments& arguments, const std::string& method);
constexpr int kDefaultGatherRays = 16;

nlohmann::json ivg_stats_json(const IvgStats& stats);

}  // namespace rc
