// radcache's --help, formatted by CLI11 from the commands' declarations: the program's (its
// commands, one line each), a command group's (its subcommands) and a command's (usage,
// description and a table of its options).
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "app/command_line.h"

namespace rc {

class HelpFormatter : public CLI::FormatterBase {
   public:
    explicit HelpFormatter(const CommandLine& line) : line_(line) {}
    // `app` is the subcommand of `command`.
    void add_command(const CLI::App* app, const CommandSpec* command) { commands_[app] = command; }

    std::string make_help(const CLI::App* app, std::string name,
                          CLI::AppFormatMode mode) const override;
    // "usage: radcache COMMAND [options]" and a line for each command.
    std::string program_help() const;
    // "usage: radcache bench all|rays|pt [options]"
    std::string group_help(const CLI::App& group) const;

   private:
    std::string command_help(const CLI::App& app, const CommandSpec& command) const;

    const CommandLine& line_;
    std::map<const CLI::App*, const CommandSpec*> commands_;
};

}  // namespace rc
