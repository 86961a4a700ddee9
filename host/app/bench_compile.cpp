// `radcache bench compile`: cold and warm build time of every kernel program.
#include <unistd.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/device_options.h"
#include "device/embedded_sources.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

// Every entry file (a .cl anywhere under kernels/) of the embedded sources.
std::vector<std::string> program_entries() {
    std::vector<std::string> entries;
    for (size_t i = 0; i < kEmbeddedSourceCount; ++i) {
        const std::string path = kEmbeddedSources[i].path;
        if (path.size() > 3 && path.ends_with(".cl")) {
            entries.push_back(path);
        }
    }
    return entries;
}

double build_all(const ContextOptions& options, const std::vector<std::string>& entries,
                 std::vector<double>& per_program) {
    Context context(options);
    double total = 0.0;
    per_program.clear();
    for (const std::string& entry : entries) {
        const double seconds = context.program(entry).report().seconds;
        per_program.push_back(seconds);
        total += seconds;
    }
    return total;
}

std::vector<OptionSpec> bench_compile_options() {
    std::vector<OptionSpec> specs = {{"--json", "", "FILE", "also write the results as JSON"}};
    for (OptionSpec& spec : device_option_specs()) {
        if (spec.name == "--device" || spec.name == "--kernel-dir") {
            specs.push_back(std::move(spec));
        }
    }
    return specs;
}

int bench_compile(const ParsedArguments& arguments) {
    // Fresh caches: ours, and PoCL's (read when the first OpenCL call initialises PoCL).
    char pattern[] = "/tmp/radcache-bench-compile-XXXXXX";
    const char* scratch = ::mkdtemp(pattern);
    if (scratch == nullptr) {
        throw Error("cannot create a scratch directory under /tmp");
    }
    const std::filesystem::path scratch_dir = scratch;
    ::setenv("POCL_CACHE_DIR", (scratch_dir / "pocl").c_str(), 1);
    ContextOptions options = context_options(arguments);
    options.cache_dir = scratch_dir / "radcache";

    const std::vector<std::string> entries = program_entries();
    std::vector<double> cold_each;
    std::vector<double> warm_each;
    const double cold = build_all(options, entries, cold_each);
    const double warm = build_all(options, entries, warm_each);
    std::filesystem::remove_all(scratch_dir);

    std::printf("%-24s %10s %10s\n", "program", "cold s", "warm s");
    nlohmann::json report;
    for (size_t i = 0; i < entries.size(); ++i) {
        std::printf("%-24s %10.3f %10.3f\n", entries[i].c_str(), cold_each[i], warm_each[i]);
        report["programs"][entries[i]] = {{"cold_seconds", cold_each[i]},
                                          {"warm_seconds", warm_each[i]}};
    }
    std::printf("%-24s %10.3f %10.3f\n", "all", cold, warm);
    report["cold_seconds"] = cold;
    report["warm_seconds"] = warm;
    if (arguments.has("--json")) {
        write_file_atomically(arguments.value("--json"), report.dump(2) + "\n");
    }
    return 0;
}

}  // namespace

CommandSpec bench_compile_command() {
    return {
        .name = "bench compile",
        .summary = "cold and warm kernel build times",
        .description =
            "Builds every kernel program twice in fresh, empty caches: cold (compiled from\n"
            "source; PoCL's own cache also empty) and warm (loaded from the binary cache the cold\n"
            "build wrote).",
        .options = bench_compile_options(),
        .run = bench_compile};
}

}  // namespace rc
