// A compiler's build log with its locations mapped back to our kernel files: the
// program a driver builds is one expanded translation unit (KernelSources::expand) whose #line
// markers name every original file, but not every vendor honours them (NVIDIA's log says
// `<kernel>:815:1: error: ...`, AMD's `"/tmp/OCL123.cl", line 815: error: ...`). The host knows
// its own line map, so it rewrites such locations whatever the vendor's format.
#pragma once

#include <string>

namespace rc {

// `log` with every location of the forms `NAME:LINE:COL:` (NAME not one of the expanded
// source's files: `<kernel>`, `<source>`, a temporary file, a number, or empty) and
// `"NAME", line LINE:` rewritten to our file and line; locations that already name one of our
// files (the compiler honoured #line) and every other line stay as they are.
std::string map_build_log(const std::string& log, const std::string& source);

}  // namespace rc
