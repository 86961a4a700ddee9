// `radcache warmup [--method M [its options]]`: fills the kernel binary cache ahead of a render.
// Builds, all at once on their own threads (Context::prebuild), the programs the
// method with these options will build (Method::programs); without --method, every method's at
// its defaults. A render afterwards on the same device loads every program from the cache.
#include <chrono>
#include <cstdio>

#include "app/commands.h"
#include "app/device_options.h"
#include "device/device_features.h"
#include "methods/registry.h"
#include "util/error.h"

namespace rc {
namespace {

// The programs of `entry` made with `arguments` and default settings, appended to *programs.
void add_programs(const MethodEntry& entry, const ParsedArguments& arguments,
                  std::vector<ProgramRequest>* programs) {
    refuse_foreign_options(entry, arguments);
    const std::unique_ptr<Method> method = entry.create(entry.read(arguments), MethodSettings{});
    for (ProgramRequest& request : method->programs()) {
        programs->push_back(std::move(request));
    }
}

std::vector<OptionSpec> warmup_options() {
    std::vector<OptionSpec> specs = with_device_options(
        {{"--method", "", "NAME",
          "the method (with its options) whose programs to build (default: every method at its "
          "defaults)"}});
    for (OptionSpec& spec : method_option_specs()) {
        specs.push_back(std::move(spec));
    }
    return specs;
}

int warmup(const ParsedArguments& arguments) {
    if (!arguments.positionals().empty()) {
        throw Error("radcache warmup takes no positional argument ('" +
                        arguments.positionals().front() + "')",
                    kExitUsage);
    }
    std::vector<ProgramRequest> programs;
    if (arguments.has("--method")) {
        add_programs(find_method(arguments.value("--method")), arguments, &programs);
    } else {
        for (const MethodEntry& entry : method_registry()) {
            add_programs(entry, arguments, &programs);
        }
    }
    programs.push_back({kDeviceFeaturesProgram, ""});  // the loop probe's, before every render
    const auto start = std::chrono::steady_clock::now();
    Context context(context_options(arguments));
    context.prebuild(programs);
    for (const ProgramRequest& request : context.prebuild_requests()) {
        context.program(request.entry, request.options);
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double summed = 0.0;
    int compiled = 0;
    for (const ProgramBuildReport& build : context.program_builds()) {
        std::printf("%-8s %6.2f s  %s %s\n", build.from_cache ? "cached" : "compiled",
                    build.seconds, build.entry.c_str(), build.options.c_str());
        summed += build.seconds;
        compiled += build.from_cache ? 0 : 1;
    }
    std::printf("%zu programs (%d compiled) on %s in %.2f s (%.2f s summed over the programs)\n",
                context.program_builds().size(), compiled, context.device().name.c_str(), wall,
                summed);
    return 0;
}

}  // namespace

CommandSpec warmup_command() {
    return {.name = "warmup",
            .summary = "build the kernel programs a render needs into the binary cache",
            .usage = "radcache warmup [--method NAME [its options]] [options]",
            .description =
                "Builds the kernel programs a render will need into the binary "
                "cache, all at once, so that\nthe render loads them instead of "
                "compiling them.",
            .options = warmup_options(),
            .run = warmup};
}

}  // namespace rc
