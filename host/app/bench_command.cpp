#include <iostream>

#include "app/commands.h"
#include "util/error.h"

namespace rc {

int run_bench_command(const std::vector<std::string>& args) {
    if (args.empty() || args[0] == "--help" || args[0] == "-h") {
        std::cout << "usage: radcache bench rays|compile [options]\n";
        return args.empty() ? kExitUsage : 0;
    }
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "rays") {
        return run_bench_rays(rest);
    }
    if (args[0] == "compile") {
        return run_bench_compile(rest);
    }
    throw Error("unknown benchmark '" + args[0] + "' (rays, compile)", kExitUsage);
}

}  // namespace rc
