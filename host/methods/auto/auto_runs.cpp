#include "methods/auto/auto_runs.h"

#include "methods/registry.h"
#include "util/cli.h"
#include "util/error.h"
#include "util/log.h"

namespace rc {
namespace {

const OptionSpec& declared_option(const MethodEntry& entry, const std::string& name) {
    for (const OptionSpec& spec : entry.options) {
        if (spec.name == name) {
            return spec;
        }
    }
    throw Error("--method auto: " + entry.name + " has no option " + name, kExitUsage);
}

ParsedArguments run_arguments(const MethodEntry& entry, const MethodRun& run) {
    ParsedArguments arguments;
    for (const auto& [name, value] : run.options) {
        const OptionSpec& spec = declared_option(entry, name);
        if (spec.value_name.empty()) {
            arguments.add(spec, {});
            continue;
        }
        const std::string refused = check_value(spec.check, value);
        if (!refused.empty()) {
            throw Error("--method auto: " + entry.name + " " + name + ": " + refused, kExitUsage);
        }
        arguments.add(spec, {value});
    }
    return arguments;
}

// Restores the quiet setting of the log when it goes out of scope.
class QuietScope {
   public:
    QuietScope() : was_quiet_(quiet()) { set_quiet(true); }
    ~QuietScope() { set_quiet(was_quiet_); }
    QuietScope(const QuietScope&) = delete;
    QuietScope& operator=(const QuietScope&) = delete;

   private:
    bool was_quiet_;
};

}  // namespace

std::string MethodRun::command_line() const {
    std::string line = method;
    for (const auto& [name, value] : options) {
        line += " " + name + (value.empty() ? "" : " " + value);
    }
    return line;
}

std::unique_ptr<Method> make_method(const MethodRun& run, const MethodSettings& settings) {
    const MethodEntry& entry = find_method(run.method);
    return entry.create(entry.read(run_arguments(entry, run)), settings);
}

double declared_default(const std::string& method, const std::string& option) {
    for (const OptionInfo& info : find_method(method).table) {
        if (info.spec.name == option) {
            try {
                return std::stod(info.default_text);
            } catch (const std::exception&) {
                break;
            }
        }
    }
    throw Error("--method auto: " + method + " states no numeric default for " + option);
}

FrameHooks quiet_hooks(const FrameHooks& hooks) {
    FrameHooks quiet;
    quiet.progress = [](double, const std::string&) {};
    quiet.intermediate = [](int, const Image&) {};
    quiet.visit_frame = hooks.visit_frame;
    return quiet;
}

FrameResult render_quietly(Method& method, const FrameScene& frame, const FrameHooks& hooks) {
    const QuietScope scope;
    return method.render_frame(frame, quiet_hooks(hooks));
}

}  // namespace rc
