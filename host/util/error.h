// The error type of radcache: a message for the user, shown as one line where possible, and the
// process exit status it leads to.
#pragma once

#include <stdexcept>
#include <string>

namespace rc {

// Exit statuses: 1 for failures of the work itself (bad input files, I/O, device errors),
// 2 for bad command lines and unusable device set-ups, and 2 as well for a well-formed scene file
// that asks for what radcache does not do (an imported pbrt-v4 or glTF file's refused directive,
// shape, light, material or parameter): the file is not broken, the request is refused.
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitUnsupported = 2;

class Error : public std::runtime_error {
   public:
    explicit Error(const std::string& message, int exit_code = kExitFailure)
        : std::runtime_error(message), exit_code_(exit_code) {}
    int exit_code() const { return exit_code_; }

   private:
    int exit_code_;
};

}  // namespace rc
