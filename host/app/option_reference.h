// What the option tables say, printed: a method's quality knobs (`render --list-knobs`, as text
// or JSON, for the sweeps and any automatic tuning) and the whole command-line reference
// (`radcache reference`, which docs/command-line.md is).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "app/command_line.h"
#include "methods/method.h"

namespace rc {

// One option of a table as JSON: name, value, type, default (and how it follows other options),
// min and max or choices, unit, knob direction, help.
nlohmann::json option_json(const OptionInfo& info);

// The method's quality knobs (knob != kNone), as JSON ({"method": ..., "knobs": [...]}).
nlohmann::json knobs_json(const MethodEntry& method);

// The same as lines of text: name, default, range, direction, help.
std::string knobs_text(const MethodEntry& method);

// Every command's options and every method's table, in Markdown.
std::string command_line_reference(const CommandLine& line);

}  // namespace rc
