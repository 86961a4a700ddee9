#include "util/cli.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "util/error.h"
#include "util/text.h"

namespace rc {

OptionSpec OptionSpec::integers(long long min, long long max,
                                std::vector<std::string> words) const {
    OptionSpec spec = *this;
    spec.check.kind = ValueCheck::Kind::kInteger;
    spec.check.integer_min = min;
    spec.check.integer_max = max;
    spec.check.words = std::move(words);
    return spec;
}

OptionSpec OptionSpec::numbers(double min, double max) const {
    OptionSpec spec = *this;
    spec.check.kind = ValueCheck::Kind::kNumber;
    spec.check.number_min = min;
    spec.check.number_max = max;
    return spec;
}

OptionSpec OptionSpec::one_of(std::vector<std::string> choices) const {
    OptionSpec spec = *this;
    spec.check.kind = ValueCheck::Kind::kChoice;
    spec.check.words = std::move(choices);
    return spec;
}

namespace {

bool parse_integer(const std::string& text, long long* value) {
    char* end = nullptr;
    errno = 0;
    *value = std::strtoll(text.c_str(), &end, 10);
    return !text.empty() && *end == '\0' && errno == 0;
}

bool parse_number(const std::string& text, double* value) {
    char* end = nullptr;
    *value = std::strtod(text.c_str(), &end);
    return !text.empty() && *end == '\0' && std::isfinite(*value);
}

bool is_word(const ValueCheck& check, const std::string& value) {
    for (const std::string& word : check.words) {
        if (value == word) {
            return true;
        }
    }
    return false;
}

// "a, b or c"
std::string listed(const std::vector<std::string>& words) {
    std::string list;
    for (size_t i = 0; i < words.size(); ++i) {
        list += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
    }
    return list;
}

// `v` with six significant digits ("0.001" for 1e-3f, "16", "1e+07").
std::string shortest(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

}  // namespace

std::string check_value(const ValueCheck& check, const std::string& value) {
    const std::string got = ", got '" + excerpt(value) + "'";
    switch (check.kind) {
        case ValueCheck::Kind::kAny:
            return "";
        case ValueCheck::Kind::kChoice:
            return is_word(check, value) ? "" : "expected " + listed(check.words) + got;
        case ValueCheck::Kind::kInteger: {
            long long parsed = 0;
            if (is_word(check, value) ||
                (parse_integer(value, &parsed) && parsed >= check.integer_min &&
                 parsed <= check.integer_max)) {
                return "";
            }
            return "expected an integer in [" + std::to_string(check.integer_min) + ", " +
                   std::to_string(check.integer_max) + "]" + got;
        }
        case ValueCheck::Kind::kNumber: {
            // A bound given as a float (1e-3f) is met by the value that rounds to it: "0.001".
            const auto at_least = [](double v, double bound) {
                return v >= bound || static_cast<float>(v) == static_cast<float>(bound);
            };
            double parsed = 0.0;
            if (parse_number(value, &parsed) && at_least(parsed, check.number_min) &&
                at_least(-parsed, -check.number_max)) {
                return "";
            }
            return "expected a number in [" + shortest(check.number_min) + ", " +
                   shortest(check.number_max) + "]" + got;
        }
    }
    return "";
}

void ParsedArguments::add(const OptionSpec& spec, std::vector<std::string> values) {
    values_[spec.name] = std::move(values);
    kinds_[spec.name] = spec.check.kind;
}

std::string ParsedArguments::value(const std::string& name, const std::string& fallback) const {
    const auto found = values_.find(name);
    return found == values_.end() || found->second.empty() ? fallback : found->second.back();
}

std::vector<std::string> ParsedArguments::values(const std::string& name) const {
    const auto found = values_.find(name);
    return found == values_.end() ? std::vector<std::string>{} : found->second;
}

std::vector<std::string> ParsedArguments::names() const {
    std::vector<std::string> names;
    for (const auto& [name, values] : values_) {
        names.push_back(name);
    }
    return names;
}

long long ParsedArguments::integer(const std::string& name, long long fallback) const {
    if (!has(name)) {
        return fallback;
    }
    long long parsed = 0;
    if (kinds_.at(name) != ValueCheck::Kind::kInteger || !parse_integer(value(name), &parsed)) {
        // The declaration, not the user, is wrong: an option read as an integer declares it.
        throw std::logic_error(name + " is read as an integer but not declared with integers()");
    }
    return parsed;
}

double ParsedArguments::number(const std::string& name, double fallback) const {
    if (!has(name)) {
        return fallback;
    }
    double parsed = 0.0;
    if (kinds_.at(name) != ValueCheck::Kind::kNumber || !parse_number(value(name), &parsed)) {
        throw std::logic_error(name + " is read as a number but not declared with numbers()");
    }
    return parsed;
}

}  // namespace rc
