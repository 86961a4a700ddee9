// The tokens of pbrt-v4's scene description format (docs/importing.md#pbrt-v4-import): words
// (directives and bare true/false), quoted strings, numbers and square brackets; '#' starts a
// comment that runs to the end of the line. Every token knows its line, so errors name
// "file:line".
#pragma once

#include <string>

namespace rc {

enum class PbrtTokenKind { kWord, kString, kNumber, kOpenBracket, kCloseBracket, kEnd };

struct PbrtToken {
    PbrtTokenKind kind = PbrtTokenKind::kEnd;
    std::string text;     // a word, or a string without its quotes (escapes resolved)
    double number = 0.0;  // kNumber
    int line = 0;
};

// Reads the tokens of one file's text; any lexical problem (an unterminated string, a malformed
// number, a byte that starts no token) throws Error "file:line: ...".
class PbrtTokenizer {
   public:
    PbrtTokenizer(std::string text, std::string file);

    // The next token (kEnd at the end of the text, and again after that).
    PbrtToken next();
    // The next token, left to be read by next().
    const PbrtToken& peek();
    // The line of the last token read (or peeked).
    int line() const { return line_; }
    const std::string& file() const { return file_; }
    // "file:line" of `line`.
    std::string where(int line) const { return file_ + ":" + std::to_string(line); }

   private:
    PbrtToken read();
    PbrtToken read_string();
    PbrtToken read_number();
    void skip_space_and_comments();

    std::string text_;
    std::string file_;
    size_t position_ = 0;
    int line_ = 1;
    bool peeked_ = false;
    PbrtToken peeked_token_;
};

// A kind of token in words, for error lines ("a number", "'['", "the end of the file").
std::string describe_token(const PbrtToken& token);

}  // namespace rc
