// Command-line options as data: each command and each method declares its options (names, value,
// help and the values it accepts); app/command_line.cpp hands them to CLI11, which parses the
// command line, checks every value against its declaration and formats --help. An unknown option
// or a bad value is an error with exit status 2.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rc {

// The values an option accepts, checked while the command line is parsed.
struct ValueCheck {
    enum class Kind { kAny, kInteger, kNumber, kChoice };
    Kind kind = Kind::kAny;
    long long integer_min = 0;
    long long integer_max = 0;
    double number_min = 0.0;
    double number_max = 0.0;
    // kChoice: the values; kInteger: words accepted besides an integer ("auto").
    std::vector<std::string> words;
};

struct OptionSpec {
    std::string name;        // "--spp"
    std::string short_name;  // "-o", or empty
    std::string value_name;  // "N"; empty for a flag
    std::string help;
    bool repeatable = false;
    ValueCheck check;

    // This option, its value an integer in [min, max] (or one of `words`).
    OptionSpec integers(long long min, long long max, std::vector<std::string> words = {}) const;
    // This option, its value a finite number in [min, max].
    OptionSpec numbers(double min, double max) const;
    // This option, its value one of `choices`.
    OptionSpec one_of(std::vector<std::string> choices) const;
};

// Empty when `check` accepts `value`, else why not: "expected an integer in [1, 64], got '0'".
std::string check_value(const ValueCheck& check, const std::string& value);

// The options given on a command line (already checked against their OptionSpecs) and its
// positional arguments.
class ParsedArguments {
   public:
    void add(const OptionSpec& spec, std::vector<std::string> values);
    void add_positional(std::string word) { positionals_.push_back(std::move(word)); }

    bool has(const std::string& name) const { return values_.count(name) != 0; }
    std::string value(const std::string& name, const std::string& fallback = "") const;
    std::vector<std::string> values(const std::string& name) const;
    // The value of an option declared with integers() or numbers() (its range checked while
    // parsing), or `fallback` when it is not given.
    long long integer(const std::string& name, long long fallback) const;
    double number(const std::string& name, double fallback) const;
    const std::vector<std::string>& positionals() const { return positionals_; }
    // The names of the options given, sorted.
    std::vector<std::string> names() const;

   private:
    std::map<std::string, std::vector<std::string>> values_;
    std::map<std::string, ValueCheck::Kind> kinds_;
    std::vector<std::string> positionals_;
};

}  // namespace rc
