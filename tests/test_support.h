// Shared pieces of the tests: one OpenCL context per test program, paths, running the CLI.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "device/context.h"
#include "scene/scene.h"

namespace rc::test {

// The context every device test of this program shares (first device by the default rule,
// kernel binary cache in the build tree).
Context& shared_context();

// A fresh context with the given options on the same device.
ContextOptions default_context_options();

std::filesystem::path source_dir();
std::filesystem::path radcache_executable();
Scene load_cornell_box();

// A new empty directory under the build tree's test scratch area, removed by nobody: each test
// names its own.
std::filesystem::path scratch_dir(const std::string& name);

struct CommandResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};
// Runs `radcache <args>` with optional environment assignments ("NAME=value").
CommandResult run_radcache(const std::vector<std::string>& args,
                           const std::vector<std::string>& environment = {});

}  // namespace rc::test
