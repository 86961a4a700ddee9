// The radcache command line as data: its commands, each with its usage, help and options
// (util/cli.h), parsed with CLI11 into subcommands, which checks every value against its
// declaration and formats --help (app/help_format.cpp).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "util/cli.h"

namespace rc {

struct CommandSpec {
    std::string name;         // "render", or "bench rays": the subcommand rays of bench
    std::string synopsis;     // its line in `radcache --help`: "render SCENE" (unset: the name)
    std::string summary;      // what it does, on that line
    std::string usage;        // "radcache render SCENE [options]" (unset: see fill_in_usage)
    std::string description;  // the paragraph of its --help
    std::vector<OptionSpec> options;
    // Runs the command on its checked options and positional arguments; returns the exit status.
    std::function<int(const ParsedArguments& arguments)> run;
};

// A command whose subcommands are commands ("bench"); `noun` names them in errors
// ("unknown benchmark 'x'").
struct CommandGroup {
    std::string name;
    std::string noun;
};

struct CommandLine {
    std::string program;  // "radcache"
    std::string version;  // what --version prints
    std::vector<CommandGroup> groups;
    std::vector<CommandSpec> commands;
};

// `command` with its unset synopsis and usage filled in: the synopsis is the name, the usage line
// "PROGRAM SYNOPSIS", followed by " [options]" when the command has options.
CommandSpec fill_in_usage(const std::string& program, CommandSpec command);

// Parses `words` (the arguments after the program's name) and runs the command they name.
// --help prints the help of the command named (exit status 0); a bad command line is an
// rc::Error with exit status 2 naming the option or the value.
int run_command_line(const CommandLine& line, const std::vector<std::string>& words);

}  // namespace rc
