// The subcommands of `radcache`. Each takes the words after its name and returns the exit
// status; errors are thrown as rc::Error.
#pragma once

#include <string>
#include <vector>

namespace rc {

int run_devices_command(const std::vector<std::string>& args);
int run_render_command(const std::vector<std::string>& args);
int run_compare_command(const std::vector<std::string>& args);
int run_warmup_command(const std::vector<std::string>& args);
int run_convert_command(const std::vector<std::string>& args);
int run_bench_command(const std::vector<std::string>& args);
int run_bench_all(const std::vector<std::string>& args);
int run_bench_rays(const std::vector<std::string>& args);
int run_bench_compile(const std::vector<std::string>& args);
int run_bench_pt(const std::vector<std::string>& args);
int run_bench_sh(const std::vector<std::string>& args);

// scenes/<name>/scene.json of the working directory, else of the source tree radcache was built
// from; Error (exit status 2) naming --scene when neither exists.
std::string shipped_scene(const std::string& name);

}  // namespace rc
