#include "util/cli.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "util/error.h"
#include "util/text.h"

namespace rc {

std::string ParsedArguments::value(const std::string& name, const std::string& fallback) const {
    const auto found = values_.find(name);
    return found == values_.end() ? fallback : found->second.back();
}

std::vector<std::string> ParsedArguments::values(const std::string& name) const {
    const auto found = values_.find(name);
    return found == values_.end() ? std::vector<std::string>{} : found->second;
}

long long ParsedArguments::integer(const std::string& name, long long fallback, long long min,
                                   long long max) const {
    if (!has(name)) {
        return fallback;
    }
    const std::string text = value(name);
    char* end = nullptr;
    errno = 0;
    const long long parsed = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || parsed < min || parsed > max) {
        throw Error(name + ": expected an integer in [" + std::to_string(min) + ", " +
                        std::to_string(max) + "], got '" + excerpt(text) + "'",
                    kExitUsage);
    }
    return parsed;
}

double ParsedArguments::number(const std::string& name, double fallback, double min,
                               double max) const {
    if (!has(name)) {
        return fallback;
    }
    const std::string text = value(name);
    char* end = nullptr;
    const double parsed = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(parsed) || parsed < min || parsed > max) {
        throw Error(name + ": expected a number in [" + std::to_string(min) + ", " +
                        std::to_string(max) + "], got '" + excerpt(text) + "'",
                    kExitUsage);
    }
    return parsed;
}

ParsedArguments parse_arguments(const std::string& command, const std::vector<std::string>& args,
                                const std::vector<OptionSpec>& specs) {
    ParsedArguments parsed;
    auto find = [&](const std::string& word) -> const OptionSpec* {
        for (const OptionSpec& spec : specs) {
            if (word == spec.name || (!spec.short_name.empty() && word == spec.short_name)) {
                return &spec;
            }
        }
        return nullptr;
    };
    for (size_t i = 0; i < args.size(); ++i) {
        std::string word = args[i];
        if (word == "--help" || word == "-h") {
            parsed.values_["--help"].push_back("");
            continue;
        }
        if (word.size() < 2 || word[0] != '-' || word == "--") {
            parsed.positionals_.push_back(word);
            continue;
        }
        std::string inline_value;
        bool has_inline_value = false;
        if (const size_t equals = word.find('=');
            word.rfind("--", 0) == 0 && equals != std::string::npos) {
            inline_value = word.substr(equals + 1);
            word = word.substr(0, equals);
            has_inline_value = true;
        }
        const OptionSpec* spec = find(word);
        if (spec == nullptr && !has_inline_value && word.size() > 2 && word[1] != '-') {
            // A short option glued to its value: -Dkey=value.
            spec = find(word.substr(0, 2));
            if (spec != nullptr && !spec->value_name.empty()) {
                inline_value = word.substr(2);
                has_inline_value = true;
                word = word.substr(0, 2);
            } else {
                spec = nullptr;
            }
        }
        if (spec == nullptr) {
            throw Error("unknown option '" + excerpt(word) + "' for '" + command + "' (see " +
                            command + " --help)",
                        kExitUsage);
        }
        if (!spec->repeatable && parsed.has(spec->name)) {
            throw Error("option " + spec->name + " given twice", kExitUsage);
        }
        if (spec->value_name.empty()) {
            if (has_inline_value) {
                throw Error("option " + spec->name + " takes no value", kExitUsage);
            }
            parsed.values_[spec->name].push_back("");
            continue;
        }
        if (!has_inline_value) {
            if (i + 1 >= args.size()) {
                throw Error("option " + spec->name + " needs a value (" + spec->value_name + ")",
                            kExitUsage);
            }
            inline_value = args[++i];
        }
        parsed.values_[spec->name].push_back(inline_value);
    }
    return parsed;
}

std::string format_help(const std::string& usage, const std::string& description,
                        const std::vector<OptionSpec>& specs) {
    std::string help = "usage: " + usage + "\n\n" + description + "\n";
    if (specs.empty()) {
        return help;
    }
    help += "\noptions:\n";
    std::vector<std::string> left;
    size_t width = 0;
    for (const OptionSpec& spec : specs) {
        std::string text = spec.short_name.empty() ? spec.name : spec.short_name + ", " + spec.name;
        if (!spec.value_name.empty()) {
            text += " " + spec.value_name;
        }
        width = std::max(width, text.size());
        left.push_back(text);
    }
    for (size_t i = 0; i < specs.size(); ++i) {
        help +=
            "  " + left[i] + std::string(width - left[i].size() + 2, ' ') + specs[i].help + "\n";
    }
    return help;
}

}  // namespace rc
