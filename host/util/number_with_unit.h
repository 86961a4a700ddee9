// A length option's value: a number with an optional unit ("0.2", "0.2u", "5%", "4px"), as
// --ic-min-spacing, --alpha and --decomp-cluster take it.
#pragma once

#include <string>

namespace rc {

struct NumberWithUnit {
    float value = 0.0f;
    std::string unit;  // one of the units, empty when not given
};

// `text` as a number with an optional unit, white space allowed around either; `units` are the
// alternatives of a regular expression ("u|%"). Not of that form: Error (exit status 2)
// "OPTION: expected EXPECTED, got 'TEXT'".
NumberWithUnit parse_number_with_unit(const std::string& option, const std::string& text,
                                      const std::string& units, const std::string& expected);

}  // namespace rc
