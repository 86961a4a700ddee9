#include "app/help_format.h"

#include <algorithm>

namespace rc {
namespace {

// The left column of an option's row: "-o, --output FILE".
std::string option_words(const CLI::Option& option) {
    std::string words;
    for (const std::string& name : option.get_snames()) {
        words += (words.empty() ? "-" : ", -") + name;
    }
    for (const std::string& name : option.get_lnames()) {
        words += (words.empty() ? "--" : ", --") + name;
    }
    const std::string value = option.get_type_name();
    return value.empty() ? words : words + " " + value;
}

// "options:" and a row for each option but --help and the positional arguments, the help
// texts aligned in one column.
std::string options_table(const CLI::App& app) {
    std::vector<std::pair<std::string, std::string>> rows;
    size_t width = 0;
    for (const CLI::Option* option : app.get_options()) {
        if (option == app.get_help_ptr() || option->get_positional()) {
            continue;
        }
        rows.emplace_back(option_words(*option), option->get_description());
        width = std::max(width, rows.back().first.size());
    }
    if (rows.empty()) {
        return "";
    }
    std::string table = "\noptions:\n";
    for (const auto& [words, help] : rows) {
        table += "  " + words + std::string(width - words.size() + 2, ' ') + help + "\n";
    }
    return table;
}

}  // namespace

std::string HelpFormatter::make_help(const CLI::App* app, std::string, CLI::AppFormatMode) const {
    const auto command = commands_.find(app);
    if (command != commands_.end()) {
        return command_help(*app, *command->second);
    }
    return app->get_parent() == nullptr ? program_help() : group_help(*app);
}

std::string HelpFormatter::program_help() const {
    std::string help = "usage: " + line_.program + " COMMAND [options]\n\ncommands:\n";
    for (const CommandSpec& command : line_.commands) {
        // Summaries from column 19; a longer synopsis keeps two spaces before its summary.
        const size_t size = command.synopsis.size();
        help += "  " + command.synopsis + std::string(size <= 16 ? 17 - size : 2, ' ') +
                command.summary + "\n";
    }
    return help + "\n" + line_.program + " COMMAND --help describes a command's options.\n";
}

std::string HelpFormatter::group_help(const CLI::App& group) const {
    std::string names;
    for (const CLI::App* sub : group.get_subcommands([](const CLI::App*) { return true; })) {
        names += (names.empty() ? "" : "|") + sub->get_name();
    }
    return "usage: " + line_.program + " " + group.get_name() + " " + names + " [options]\n";
}

std::string HelpFormatter::command_help(const CLI::App& app, const CommandSpec& command) const {
    return "usage: " + command.usage + "\n\n" + command.description + "\n" + options_table(app);
}

}  // namespace rc
