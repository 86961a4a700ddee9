#include <filesystem>
#include <iostream>

#include "app/commands.h"
#include "util/error.h"

namespace rc {

int run_bench_command(const std::vector<std::string>& args) {
    if (args.empty() || args[0] == "--help" || args[0] == "-h") {
        std::cout << "usage: radcache bench all|rays|pt|sh|compile [options]\n";
        return args.empty() ? kExitUsage : 0;
    }
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "all") {
        return run_bench_all(rest);
    }
    if (args[0] == "rays") {
        return run_bench_rays(rest);
    }
    if (args[0] == "pt") {
        return run_bench_pt(rest);
    }
    if (args[0] == "sh") {
        return run_bench_sh(rest);
    }
    if (args[0] == "compile") {
        return run_bench_compile(rest);
    }
    throw Error("unknown benchmark '" + args[0] + "' (all, rays, pt, sh, compile)", kExitUsage);
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

}  // namespace rc
