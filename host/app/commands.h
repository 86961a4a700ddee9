// The subcommands of `radcache`. Each takes the words after its name and returns the exit
// status; errors are thrown as rc::Error.
#pragma once

#include <string>
#include <vector>

namespace rc {

int run_devices_command(const std::vector<std::string>& args);
int run_render_command(const std::vector<std::string>& args);
int run_bench_command(const std::vector<std::string>& args);
int run_bench_rays(const std::vector<std::string>& args);
int run_bench_compile(const std::vector<std::string>& args);

}  // namespace rc
