#include "util/text.h"

#include <cstdio>

namespace rc {

std::string excerpt(std::string_view text, size_t limit) {
    std::string out;
    size_t used = 0;
    for (; used < text.size() && out.size() < limit; ++used) {
        const auto c = static_cast<unsigned char>(text[used]);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\\') {
            out += "\\\\";
        } else if (c < 0x20 || c == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
            out += escaped;
        } else {
            out += static_cast<char>(c);
        }
    }
    if (used < text.size()) {
        out += "... (" + std::to_string(text.size()) + " bytes)";
    }
    return out;
}

}  // namespace rc
