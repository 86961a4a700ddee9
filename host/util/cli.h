// Command-line options: declared per command, parsed strictly (an unknown option or a bad value
// is an error with exit status 2), and listed in --help.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rc {

struct OptionSpec {
    std::string name;        // "--spp"
    std::string short_name;  // "-o", or empty
    std::string value_name;  // "N"; empty for a flag
    std::string help;
    bool repeatable = false;
};

class ParsedArguments {
   public:
    bool has(const std::string& name) const { return values_.count(name) != 0; }
    std::string value(const std::string& name, const std::string& fallback = "") const;
    std::vector<std::string> values(const std::string& name) const;
    // An integer in [min, max]; Error naming the option otherwise.
    long long integer(const std::string& name, long long fallback, long long min,
                      long long max) const;
    double number(const std::string& name, double fallback, double min, double max) const;
    const std::vector<std::string>& positionals() const { return positionals_; }

   private:
    friend ParsedArguments parse_arguments(const std::string&, const std::vector<std::string>&,
                                           const std::vector<OptionSpec>&);
    std::map<std::string, std::vector<std::string>> values_;
    std::vector<std::string> positionals_;
};

// Parses `args` (after the command words) against `specs`; --help is always accepted.
ParsedArguments parse_arguments(const std::string& command, const std::vector<std::string>& args,
                                const std::vector<OptionSpec>& specs);

// "usage: <usage>\n\n<description>\n\noptions:\n  --name VALUE  help\n..."
std::string format_help(const std::string& usage, const std::string& description,
                        const std::vector<OptionSpec>& specs);

}  // namespace rc
