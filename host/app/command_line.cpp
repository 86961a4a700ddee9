#include "app/command_line.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <deque>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <vector>

#include "app/help_format.h"
#include "util/error.h"
#include "util/new_folders.h"
#include "util/text.h"

namespace rc {
namespace {

// A command's CLI11 subcommand: its options as declared and as CLI11 holds them, and its
// positional arguments.
struct BoundCommand {
    const CommandSpec* command = nullptr;
    CLI::App* app = nullptr;
    std::vector<std::pair<const OptionSpec*, CLI::Option*>> options;
    std::vector<std::string> positionals;
};

// `spec` as a CLI11 option of `app`: a flag or an option taking one value per occurrence,
// given once unless repeatable, its value checked by check_value().
CLI::Option* add_option(CLI::App& app, const OptionSpec& spec) {
    const std::string names =
        spec.short_name.empty() ? spec.name : spec.short_name + "," + spec.name;
    CLI::Option* option = nullptr;
    if (spec.value_name.empty()) {
        option = app.add_flag(names, spec.help)->disable_flag_override();
    } else {
        option = app.add_option(names, spec.help)->type_name(spec.value_name);
    }
    option->multi_option_policy(spec.repeatable ? CLI::MultiOptionPolicy::TakeAll
                                                : CLI::MultiOptionPolicy::Throw);
    if (spec.check.kind != ValueCheck::Kind::kAny) {
        const ValueCheck check = spec.check;
        option->check(CLI::Validator(
            [check](const std::string& value) { return check_value(check, value); }, ""));
    }
    return option;
}

// The subcommand of `command` under `parent`, its options and a catch-all positional argument.
void bind_command(CLI::App& parent, const std::string& name, BoundCommand& bound) {
    bound.app = parent.add_subcommand(name, bound.command->summary);
    bound.app->allow_extras(true);
    std::set<std::string> seen;  // an option declared twice is one option (the first)
    for (const OptionSpec& spec : bound.command->options) {
        if (seen.insert(spec.name).second) {
            bound.options.emplace_back(&spec, add_option(*bound.app, spec));
        }
    }
    bound.app->add_option("arguments", bound.positionals);
}

// The CLI11 application of a command line: the program, its command groups and commands.
struct CommandTree {
    explicit CommandTree(const CommandLine& line)
        : formatter(std::make_shared<HelpFormatter>(line)), root(line.program) {
        root.formatter(formatter);
        root.set_help_flag("-h,--help", "print this help");
        root.allow_extras(true);
        const std::string version_help = "print the version";
        version = root.add_flag("--version", version_help);
        for (const CommandSpec& command : line.commands) {
            CLI::App* parent = &root;
            std::string name = command.name;
            if (const size_t space = name.find(' '); space != std::string::npos) {
                parent = group(name.substr(0, space));
                name = name.substr(space + 1);
            }
            bound.push_back({&command});
            bind_command(*parent, name, bound.back());
            formatter->add_command(bound.back().app, &command);
        }
    }

    CLI::App* group(const std::string& name) {
        const std::vector<CLI::App*> existing =
            root.get_subcommands([&](CLI::App* app) { return app->get_name() == name; });
        if (!existing.empty()) {
            return existing.front();
        }
        CLI::App* added = root.add_subcommand(name);
        added->allow_extras(true);
        return added;
    }

    // The subcommand the command line selected, the deepest one.
    CLI::App* selected() {
        CLI::App* app = &root;
        while (!app->get_subcommands().empty()) {
            app = app->get_subcommands().front();
        }
        return app;
    }

    std::shared_ptr<HelpFormatter> formatter;
    CLI::App root;
    CLI::Option* version = nullptr;
    std::deque<BoundCommand> bound;  // addresses stay put: CLI11 fills `positionals`
};

// The name of the option a CLI11 message starts with ("--width: 1 required N missing").
std::string leading_option(const std::string& message, const CLI::App& app) {
    const std::string name = message.substr(0, message.find_first_of(": "));
    if (name.rfind("-", 0) == 0) {
        return name;
    }
    // A flag override names the flag without its dashes.
    const CLI::Option* option = app.get_option_no_throw("--" + name);
    return option != nullptr ? "--" + name : "-" + name;
}

// CLI11's parse error as radcache's one line (exit status 2).
Error usage_error(const CLI::ParseError& error, const CLI::App& app) {
    const std::string message = error.what();
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr) {
        const std::string name = leading_option(message, app);
        const CLI::Option* option = app.get_option_no_throw(name);
        if (message.find(" required ") != std::string::npos && message.size() >= 8 &&
            message.compare(message.size() - 8, 8, " missing") == 0) {
            const std::string value = option != nullptr ? option->get_type_name() : "";
            return Error("option " + name + " needs a value (" + value + ")", kExitUsage);
        }
        if (message.find("At Most") != std::string::npos) {
            return Error("option " + name + " given twice", kExitUsage);
        }
        if (message.find("disallowed flag override") != std::string::npos) {
            return Error("option " + name + " takes no value", kExitUsage);
        }
    }
    return Error(message, kExitUsage);
}

// The arguments CLI11 matched to no option or subcommand of `app`.
std::vector<std::string> unmatched(const CLI::App& app) { return app.remaining(); }

std::string subcommand_list(const CLI::App& group) {
    std::string names;
    for (const CLI::App* sub : group.get_subcommands([](const CLI::App*) { return true; })) {
        names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    return names;
}

// `app` (the program or a command group) has arguments left that name none of its commands, or
// is where the command line ends: the error, or its help, with exit status 2.
int refuse_command(const CommandLine& line, CommandTree& tree, CLI::App& app) {
    const std::vector<std::string> words = unmatched(app);
    if (&app == &tree.root) {
        if (words.empty()) {
            std::cout << tree.formatter->program_help();
        } else {
            std::cerr << line.program << ": error: unknown command '" << excerpt(words[0]) << "'\n"
                      << tree.formatter->program_help();
        }
        return kExitUsage;
    }
    if (words.empty()) {
        std::cout << tree.formatter->group_help(app);
        return kExitUsage;
    }
    std::string noun = "command";
    for (const CommandGroup& group : line.groups) {
        noun = group.name == app.get_name() ? group.noun : noun;
    }
    throw Error("unknown " + noun + " '" + excerpt(words[0]) + "' (" + subcommand_list(app) + ")",
                kExitUsage);
}

// The command's options and its positional arguments, those after "--" last.
ParsedArguments parsed_arguments(const BoundCommand& bound,
                                 const std::vector<std::string>& after_dashes) {
    ParsedArguments arguments;
    for (const auto& [spec, option] : bound.options) {
        if (option->count() > 0) {
            // A flag has no value: one empty one per occurrence.
            arguments.add(*spec, spec->value_name.empty()
                                     ? std::vector<std::string>(option->count(), "")
                                     : option->results());
        }
    }
    for (const std::string& word : bound.positionals) {
        arguments.add_positional(word);
    }
    for (const std::string& word : after_dashes) {
        arguments.add_positional(word);
    }
    return arguments;
}

// Runs `bound`'s command unless the command line gave it an option it does not declare.
int run_command(const CommandLine& line, const BoundCommand& bound,
                const std::vector<std::string>& after_dashes) {
    const std::string command = line.program + " " + bound.command->name;
    if (const std::vector<std::string> extra = unmatched(*bound.app); !extra.empty()) {
        throw Error("unknown option '" + excerpt(extra[0].substr(0, extra[0].find('='))) +
                        "' for '" + command + "' (see " + command + " --help)",
                    kExitUsage);
    }
    const ParsedArguments arguments = parsed_arguments(bound, after_dashes);
    // The folders a --dump-kernels run makes (device_options.cpp makes them before any work)
    // are removed again, when empty, if the run fails: a refused run leaves no folder.
    std::vector<std::filesystem::path> made;
    if (arguments.has("--dump-kernels")) {
        for (std::filesystem::path folder = arguments.value("--dump-kernels");
             !folder.empty() && folder != folder.parent_path(); folder = folder.parent_path()) {
            made.push_back(folder);  // deepest first, as NewFolders removes them in order
        }
    }
    NewFolders folders(made);
    const int status = bound.command->run(arguments);
    if (status == 0) {
        folders.keep();
    }
    return status;
}

}  // namespace

CommandSpec fill_in_usage(const std::string& program, CommandSpec command) {
    if (command.synopsis.empty()) {
        command.synopsis = command.name;
    }
    if (command.usage.empty()) {
        command.usage =
            program + " " + command.synopsis + (command.options.empty() ? "" : " [options]");
    }
    return command;
}

int run_command_line(const CommandLine& line, const std::vector<std::string>& words) {
    CommandTree tree(line);
    // The words after "--" are positional arguments of the command (CLI11 2.1 would hand them
    // to the program instead).
    const auto dashes = std::find(words.begin(), words.end(), "--");
    const std::vector<std::string> after_dashes(dashes == words.end() ? dashes : dashes + 1,
                                                words.end());
    std::vector<std::string> reversed(std::make_reverse_iterator(dashes), words.rend());
    try {
        if (words.empty()) {
            std::cout << tree.formatter->program_help();
            return kExitUsage;
        }
        tree.root.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        std::cout << tree.root.help();
        return 0;
    } catch (const CLI::ParseError& error) {
        throw usage_error(error, *tree.selected());
    }
    if (tree.version->count() > 0 && tree.root.get_subcommands().empty() &&
        unmatched(tree.root).empty()) {
        std::cout << line.version << "\n";
        return 0;
    }
    // The program and the command groups on the way to the command take no arguments.
    for (CLI::App* app = &tree.root;; app = app->get_subcommands().front()) {
        const auto bound = std::find_if(tree.bound.begin(), tree.bound.end(),
                                        [&](const BoundCommand& b) { return b.app == app; });
        if (bound != tree.bound.end()) {
            return run_command(line, *bound, after_dashes);
        }
        if (!unmatched(*app).empty() || app->get_subcommands().empty()) {
            return refuse_command(line, tree, *app);
        }
    }
}

}  // namespace rc
