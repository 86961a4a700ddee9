#include "util/number_with_unit.h"

#include <regex>

#include "util/error.h"

namespace rc {

NumberWithUnit parse_number_with_unit(const std::string& option, const std::string& text,
                                      const std::string& units, const std::string& expected) {
    const std::regex form(R"(^\s*([0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\s*()" + units + R"()?\s*$)");
    std::smatch match;
    if (!std::regex_match(text, match, form)) {
        throw Error(option + ": expected " + expected + ", got '" + text + "'", kExitUsage);
    }
    return NumberWithUnit{std::stof(match[1].str()), match[2].str()};
}

}  // namespace rc
