// Messages on stderr: warnings always (errors under --strict), progress and notes unless quiet.
#pragma once

#include <string>

namespace rc {

void set_quiet(bool quiet);
bool quiet();
// Under strict mode (render --strict) every warning is an error: log_warning throws Error
// "<message> (a warning; --strict makes it an error)" instead of printing.
void set_strict(bool strict);
bool strict();
void log_note(const std::string& message);     // "radcache: <message>" unless quiet
void log_warning(const std::string& message);  // "radcache: warning: <message>"

}  // namespace rc
