// Messages on stderr: warnings always, progress and notes unless quiet.
#pragma once

#include <string>

namespace rc {

void set_quiet(bool quiet);
bool quiet();
void log_note(const std::string& message);     // "radcache: <message>" unless quiet
void log_warning(const std::string& message);  // "radcache: warning: <message>"

}  // namespace rc
