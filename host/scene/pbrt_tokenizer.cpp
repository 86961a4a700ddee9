#include "scene/pbrt_tokenizer.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "util/error.h"
#include "util/text.h"

namespace rc {
namespace {

bool starts_number(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
}

bool in_number(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.' ||
           c == 'e' || c == 'E';
}

bool in_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The character pbrt's escape \`escaped` stands for, or '\0' when it is none of pbrt's escapes.
char unescaped(char escaped) {
    static constexpr char kEscapes[][2] = {{'n', '\n'}, {'t', '\t'},  {'b', '\b'},  {'f', '\f'},
                                           {'r', '\r'}, {'\\', '\\'}, {'\'', '\''}, {'"', '"'}};
    for (const auto& escape : kEscapes) {
        if (escape[0] == escaped) {
            return escape[1];
        }
    }
    return '\0';
}

}  // namespace

PbrtTokenizer::PbrtTokenizer(std::string text, std::string file)
    : text_(std::move(text)), file_(std::move(file)) {}

PbrtToken PbrtTokenizer::next() {
    if (peeked_) {
        peeked_ = false;
        return std::move(peeked_token_);
    }
    return read();
}

const PbrtToken& PbrtTokenizer::peek() {
    if (!peeked_) {
        peeked_token_ = read();
        peeked_ = true;
    }
    return peeked_token_;
}

void PbrtTokenizer::skip_space_and_comments() {
    while (position_ < text_.size()) {
        const char c = text_[position_];
        if (c == '\n') {
            ++line_;
            ++position_;
        } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++position_;
        } else if (c == '#') {
            while (position_ < text_.size() && text_[position_] != '\n') {
                ++position_;
            }
        } else {
            return;
        }
    }
}

PbrtToken PbrtTokenizer::read() {
    skip_space_and_comments();
    PbrtToken token;
    token.line = line_;
    if (position_ >= text_.size()) {
        return token;
    }
    const char c = text_[position_];
    if (c == '[' || c == ']') {
        token.kind = c == '[' ? PbrtTokenKind::kOpenBracket : PbrtTokenKind::kCloseBracket;
        token.text = std::string(1, c);
        ++position_;
        return token;
    }
    if (c == '"') {
        return read_string();
    }
    if (starts_number(c)) {
        return read_number();
    }
    if (std::isalpha(static_cast<unsigned char>(c))) {
        const size_t start = position_;
        while (position_ < text_.size() && in_word(text_[position_])) {
            ++position_;
        }
        token.kind = PbrtTokenKind::kWord;
        token.text = text_.substr(start, position_ - start);
        return token;
    }
    throw Error(where(line_) + ": unexpected character '" + excerpt(std::string(1, c)) + "'");
}

// A quoted string on one line, with pbrt's escapes (\n \t \b \f \r \\ \' \").
PbrtToken PbrtTokenizer::read_string() {
    PbrtToken token;
    token.kind = PbrtTokenKind::kString;
    token.line = line_;
    const auto unterminated = [&] {
        return Error(where(token.line) + ": unterminated string \"" + excerpt(token.text) + "\"");
    };
    ++position_;  // the opening quote
    for (;;) {
        if (position_ >= text_.size() || text_[position_] == '\n') {
            throw unterminated();
        }
        const char c = text_[position_++];
        if (c == '"') {
            return token;
        }
        if (c != '\\') {
            token.text += c;
            continue;
        }
        if (position_ >= text_.size()) {
            throw unterminated();
        }
        const char escaped = text_[position_++];
        const char character = unescaped(escaped);
        if (character == '\0') {
            throw Error(where(token.line) + ": unknown escape '\\" +
                        excerpt(std::string(1, escaped)) + "' in a string");
        }
        token.text += character;
    }
}

PbrtToken PbrtTokenizer::read_number() {
    PbrtToken token;
    token.kind = PbrtTokenKind::kNumber;
    token.line = line_;
    const size_t start = position_;
    while (position_ < text_.size() && in_number(text_[position_])) {
        ++position_;
    }
    token.text = text_.substr(start, position_ - start);
    char* end = nullptr;
    token.number = std::strtod(token.text.c_str(), &end);
    const bool whole = end == token.text.c_str() + token.text.size() && !token.text.empty();
    if (!whole || !std::isfinite(token.number)) {
        throw Error(where(token.line) + ": malformed number '" + excerpt(token.text) + "'");
    }
    return token;
}

std::string describe_token(const PbrtToken& token) {
    switch (token.kind) {
        case PbrtTokenKind::kWord:
            return "'" + excerpt(token.text) + "'";
        case PbrtTokenKind::kString:
            return "the string \"" + excerpt(token.text) + "\"";
        case PbrtTokenKind::kNumber:
            return "the number " + excerpt(token.text);
        case PbrtTokenKind::kOpenBracket:
            return "'['";
        case PbrtTokenKind::kCloseBracket:
            return "']'";
        default:
            return "the end of the file";
    }
}

}  // namespace rc
