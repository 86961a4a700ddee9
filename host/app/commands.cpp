#include "app/commands.h"

#include <filesystem>

#include "util/error.h"
#include "util/output_identity.h"

namespace rc {

CommandLine radcache_command_line() {
    CommandLine line;
    line.program = "radcache";
    line.version = "radcache 0.1.0";
    line.groups = {{"bench", "benchmark"}};
    for (const CommandSpec& command :
         {devices_command(), render_command(), compare_command(), merge_command(),
          convert_command(), warmup_command(), bench_all_command(), bench_rays_command(),
          bench_pt_command(), bench_sh_command(), bench_insertion_command(),
          bench_compile_command(), reference_command()}) {
        line.commands.push_back(fill_in_usage(line.program, command));
    }
    return line;
}

int run_render_command(const std::vector<std::string>& args) {
    std::vector<std::string> words = {"render"};
    words.insert(words.end(), args.begin(), args.end());
    return run_command_line(radcache_command_line(), words);
}

std::string shipped_scene(const std::string& name) {
    const std::string relative = "scenes/" + name + "/scene.json";
    for (const std::string& candidate :
         {relative, std::string(RADCACHE_SOURCE_DIR) + "/" + relative}) {
        if (std::filesystem::is_regular_file(candidate)) {
            return candidate;
        }
    }
    throw Error("cannot find " + relative + "; pass --scene", kExitUsage);
}

void check_bench_files(const ParsedArguments& arguments, const std::vector<std::string>& scenes) {
    if (!arguments.has("--json")) {
        return;
    }
    RunFiles run;
    for (const std::string& scene : scenes) {
        run.input("scene file", scene);
    }
    if (arguments.has("--cache-in")) {
        run.input("--cache-in file", arguments.value("--cache-in"));
    }
    run.output("--json", arguments.value("--json"));
    run.check();
}

}  // namespace rc
