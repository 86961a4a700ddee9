// Text for error lines: untrusted values quoted short, on one line.
#pragma once

#include <string>
#include <string_view>

namespace rc {

// The longest excerpt of a value an error line quotes.
inline constexpr size_t kQuoteLimit = 80;

// `text` made safe for one error line: control bytes and bytes that are not UTF-8 escaped (\n,
// \x1b, \xff; well-formed UTF-8 kept: "café"), cut to at
// most `limit` characters with "..." and the full length when longer ("abc... (5000000 bytes)").
std::string excerpt(std::string_view text, size_t limit = kQuoteLimit);

}  // namespace rc
