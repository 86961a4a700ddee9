// JSON text to nlohmann::json for the scene files, strictly: comments allowed, but no key twice
// in one object, no number out of range, and a bounded nesting depth; and JSON values
// quoted short in error lines.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace rc {

// The deepest nesting of arrays and objects parse_json accepts.
inline constexpr int kMaxJsonDepth = 64;

// Parses JSON text (comments allowed). A syntax error or a number out of range throws Error with
// the file, line and column; nesting deeper than kMaxJsonDepth and a key given twice in one object
// throw Error with the file and the key path.
nlohmann::json parse_json(const std::string& text, const std::string& file);

// The deepest nesting of arrays and objects in JSON text, counted without parsing it (brackets
// inside strings skipped), so that a document can be refused before a library that walks it
// recursively (tinygltf's conversion of `extras`) overflows the stack.
int json_nesting_depth(std::string_view text);

// A JSON value for an error line: serialised, and cut to about kQuoteLimit characters without
// serialising more of it than that.
std::string describe_json(const nlohmann::json& value);

}  // namespace rc
