// The renders `--method auto` makes of other methods (its pilots and its plan), made through the
// registry (methods/registry.h) from option values as a command line gives them: auto includes
// no method's folder.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "methods/method.h"

namespace rc {

// A method and its options ("--accuracy", "0.35"; a flag with an empty value).
struct MethodRun {
    std::string method;
    std::vector<std::pair<std::string, std::string>> options;

    // "ic --accuracy 0.35 --ic-rays 512": the run as a command line's words.
    std::string command_line() const;
};

// The method of `run` made with `settings`; Error (exit status 2) naming an option the method
// does not declare or a value its declaration refuses.
std::unique_ptr<Method> make_method(const MethodRun& run, const MethodSettings& settings);

// The default of `method`'s `option` as its option table states it ("0.35", "1024"), read as a
// number; Error when the method does not declare it or its default is not a number.
double declared_default(const std::string& method, const std::string& option);

// Hooks that report nothing (a pilot's), visiting other frames through `hooks`.
FrameHooks quiet_hooks(const FrameHooks& hooks);

// One frame of `method`, its notes on stderr suppressed.
FrameResult render_quietly(Method& method, const FrameScene& frame, const FrameHooks& hooks);

}  // namespace rc
