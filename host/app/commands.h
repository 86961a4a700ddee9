// The commands of `radcache` (app/command_line.h): each declares its usage, help and options
// and runs on the checked arguments; errors are thrown as rc::Error.
#pragma once

#include <string>
#include <vector>

#include "app/command_line.h"

namespace rc {

// The whole command line: every command below, in the order `radcache --help` lists them.
CommandLine radcache_command_line();

// `radcache render ARGS...` in this process, as main() runs it: the exit status, or an Error.
int run_render_command(const std::vector<std::string>& args);

CommandSpec devices_command();
CommandSpec render_command();
CommandSpec compare_command();
CommandSpec merge_command();
CommandSpec convert_command();
CommandSpec warmup_command();
CommandSpec reference_command();
CommandSpec bench_all_command();
CommandSpec bench_rays_command();
CommandSpec bench_pt_command();
CommandSpec bench_sh_command();
CommandSpec bench_insertion_command();
CommandSpec bench_compile_command();

// scenes/<name>/scene.json of the working directory, else of the source tree radcache was built
// from; Error (exit status 2) naming --scene when neither exists.
std::string shipped_scene(const std::string& name);

// Error (exit status 2) when a bench's --json is one of the `scenes` it reads or its --cache-in
// (util/output_identity.h).
void check_bench_files(const ParsedArguments& arguments, const std::vector<std::string>& scenes);

}  // namespace rc
