#include "util/log.h"

#include <atomic>
#include <iostream>

namespace rc {
namespace {
std::atomic<bool> g_quiet{false};
}

void set_quiet(bool quiet) { g_quiet = quiet; }
bool quiet() { return g_quiet; }

void log_note(const std::string& message) {
    if (!g_quiet) {
        std::cerr << "radcache: " << message << "\n";
    }
}

void log_warning(const std::string& message) {
    std::cerr << "radcache: warning: " << message << "\n";
}

}  // namespace rc
