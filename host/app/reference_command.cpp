// `radcache reference`: the command-line reference in Markdown, generated from every command's
// options and every method's option table; docs/command-line.md is its output.
#include <iostream>

#include "app/commands.h"
#include "app/option_reference.h"
#include "util/error.h"

namespace rc {

CommandSpec reference_command() {
    return {.name = "reference",
            .summary = "print every command's and method's options in Markdown",
            .description =
                "Prints the command-line reference (docs/command-line.md): every "
                "command's options and every method's option table, with defaults, "
                "ranges and quality knobs.",
            .run = [](const ParsedArguments& arguments) {
                if (!arguments.positionals().empty()) {
                    throw Error("radcache reference takes no positional argument", kExitUsage);
                }
                std::cout << command_line_reference(radcache_command_line());
                return 0;
            }};
}

}  // namespace rc
