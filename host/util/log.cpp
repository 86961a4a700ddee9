#include "util/log.h"

#include <atomic>
#include <iostream>

#include "util/error.h"

namespace rc {
namespace {
std::atomic<bool> g_quiet{false};
std::atomic<bool> g_strict{false};
}  // namespace

void set_quiet(bool quiet) { g_quiet = quiet; }
bool quiet() { return g_quiet; }
void set_strict(bool strict) { g_strict = strict; }
bool strict() { return g_strict; }

void log_note(const std::string& message) {
    if (!g_quiet) {
        std::cerr << "radcache: " << message << "\n";
    }
}

void log_warning(const std::string& message) {
    if (g_strict) {
        throw Error(message + " (a warning; --strict makes it an error)");
    }
    std::cerr << "radcache: warning: " << message << "\n";
}

}  // namespace rc
