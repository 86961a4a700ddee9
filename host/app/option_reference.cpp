#include "app/option_reference.h"

#include <set>
#include <sstream>

#include "methods/registry.h"

namespace rc {
namespace {

// "[1, 64]", "trilinear|tricubic" or "" for the values an option accepts.
std::string accepted_values(const OptionInfo& info) {
    const ValueCheck& check = info.spec.check;
    std::string words;
    for (const std::string& word : check.words) {
        words += (words.empty() ? "" : "|") + word;
    }
    switch (check.kind) {
        case ValueCheck::Kind::kInteger:
            return "[" + std::to_string(check.integer_min) + ", " +
                   std::to_string(check.integer_max) + "]" + (words.empty() ? "" : " or " + words);
        case ValueCheck::Kind::kNumber:
            return "[" + option_value_text(check.number_min) + ", " +
                   option_value_text(check.number_max) + "]";
        case ValueCheck::Kind::kChoice:
            return words;
        case ValueCheck::Kind::kAny:
            break;
    }
    return "";
}

std::string default_of(const OptionInfo& info) {
    if (!info.default_note.empty()) {
        return info.default_note;
    }
    if (info.type == "flag") {
        return "off";
    }
    if (info.default_text.empty()) {
        return "none";
    }
    return info.default_text + (info.unit.empty() ? "" : " " + info.unit);
}

// A Markdown table cell: no line breaks, pipes escaped.
std::string cell(std::string text) {
    std::string out;
    for (const char c : text) {
        if (c == '|') {
            out += "\\|";
        } else if (c == '\n') {
            out += ' ';
        } else {
            out += c;
        }
    }
    return out;
}

std::string option_name(const OptionSpec& spec) {
    std::string name = "`" + spec.name;
    if (!spec.value_name.empty()) {
        name += " " + spec.value_name;
    }
    name += "`";
    if (!spec.short_name.empty()) {
        name = "`" + spec.short_name + "`, " + name;
    }
    return name;
}

void method_section(const MethodEntry& method, std::ostringstream& out) {
    out << "\n### `--method " << method.name << "`\n\n" << method.summary << ".\n\n";
    std::string layers;
    for (const std::string& aov : method.aovs) {
        layers += (layers.empty() ? "" : ", ") + ("`" + aov + "`");
    }
    out << "Layers: " << layers << ".\n";
    if (method.table.empty()) {
        out << "\nNo options of its own.\n";
        return;
    }
    out << "\n| option | default | accepts | knob | what it does |\n| --- | --- | --- | --- | --- "
           "|\n";
    for (const OptionInfo& info : method.table) {
        const std::string knob =
            info.knob == KnobDirection::kNone ? "" : knob_direction_name(info.knob);
        out << "| " << option_name(info.spec) << " | " << cell(default_of(info)) << " | "
            << cell(accepted_values(info)) << " | " << knob << " | " << cell(info.spec.help)
            << " |\n";
    }
}

void command_section(const CommandSpec& command, const std::set<std::string>& method_options,
                     std::ostringstream& out) {
    out << "\n## `radcache " << command.name << "`\n\n"
        << command.summary << ".\n\n    " << command.usage << "\n\n";
    if (!command.description.empty()) {
        out << command.description << "\n\n";
    }
    bool header = false;
    for (const OptionSpec& spec : command.options) {
        if (method_options.count(spec.name) != 0) {
            continue;
        }
        if (!header) {
            out << "| option | what it does |\n| --- | --- |\n";
            header = true;
        }
        // The first line: --method's help lists the methods after it, as the sections below do.
        out << "| " << option_name(spec) << " | " << cell(spec.help.substr(0, spec.help.find('\n')))
            << " |\n";
    }
    if (command.name == "render" || command.name == "warmup") {
        out << "\nand the options of the method (below).\n";
    }
}

}  // namespace

nlohmann::json option_json(const OptionInfo& info) {
    nlohmann::json json = {{"name", info.spec.name}, {"value", info.spec.value_name},
                           {"type", info.type},      {"default", info.default_text},
                           {"unit", info.unit},      {"knob", knob_direction_name(info.knob)},
                           {"help", info.spec.help}};
    if (!info.default_note.empty()) {
        json["default_note"] = info.default_note;
    }
    const ValueCheck& check = info.spec.check;
    if (check.kind == ValueCheck::Kind::kInteger) {
        json["min"] = check.integer_min;
        json["max"] = check.integer_max;
    } else if (check.kind == ValueCheck::Kind::kNumber) {
        json["min"] = check.number_min;
        json["max"] = check.number_max;
    }
    if (!check.words.empty()) {
        json["choices"] = check.words;
    }
    return json;
}

nlohmann::json knobs_json(const MethodEntry& method) {
    nlohmann::json knobs = nlohmann::json::array();
    for (const OptionInfo& info : method.table) {
        if (info.knob != KnobDirection::kNone) {
            knobs.push_back(option_json(info));
        }
    }
    return {{"method", method.name}, {"knobs", knobs}};
}

std::string knobs_text(const MethodEntry& method) {
    std::ostringstream out;
    out << "quality knobs of --method " << method.name << " (direction: which way buys accuracy)\n";
    for (const OptionInfo& info : method.table) {
        if (info.knob == KnobDirection::kNone) {
            continue;
        }
        const std::string accepts = accepted_values(info);
        out << "  " << info.spec.name << " " << info.spec.value_name << "  ("
            << knob_direction_name(info.knob) << "; default " << default_of(info)
            << (accepts.empty() ? "" : "; " + accepts) << ")\n      " << info.spec.help << "\n";
    }
    return out.str();
}

std::string command_line_reference(const CommandLine& line) {
    std::set<std::string> method_options;
    for (const OptionSpec& spec : method_option_specs()) {
        method_options.insert(spec.name);
    }
    std::ostringstream out;
    out << "# The command line\n\n"
        << "Generated by `radcache reference > docs/command-line.md` from the commands' option "
           "lists and the methods' option tables (a test checks it is current). How the tables "
           "work: [option-tables.md](option-tables.md).\n";
    for (const CommandSpec& command : line.commands) {
        command_section(command, method_options, out);
    }
    out << "\n## The methods' options\n\n"
        << "`radcache render --method M` takes the options of M's table; another method's option "
           "is refused, naming the methods it belongs to. A *knob* trades time for accuracy: "
           "`increase` buys accuracy with a larger value, `decrease` with a smaller one "
           "(`radcache render --method M --list-knobs --json` prints them for tools).\n";
    for (const MethodEntry& method : method_registry()) {
        method_section(method, out);
    }
    return out.str();
}

}  // namespace rc
