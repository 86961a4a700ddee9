#include "scene/pbrt_parser.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "scene/pbrt_tokenizer.h"
#include "util/error.h"
#include "util/text.h"

namespace rc {

bool is_pbrt_path(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".pbrt";
}

namespace {

// The deepest Include nesting and the most files one scene may read (an include cycle or an
// include bomb is refused, not followed).
constexpr int kMaxIncludeDepth = 32;
constexpr int kMaxIncludedFiles = 4096;

// What follows a directive's name: `numbers` numbers (bracketed or not), then `strings` quoted
// strings (a negative count: one, and a second when a string follows), then a parameter list
// when `params`.
struct Grammar {
    int numbers = 0;
    int strings = 0;
    bool params = false;
};

const std::map<std::string, Grammar>& grammars() {
    static const std::map<std::string, Grammar> table = {
        {"Translate", {3, 0, false}},
        {"Scale", {3, 0, false}},
        {"Rotate", {4, 0, false}},
        {"LookAt", {9, 0, false}},
        {"Transform", {16, 0, false}},
        {"ConcatTransform", {16, 0, false}},
        {"TransformTimes", {2, 0, false}},
        {"Identity", {}},
        {"WorldBegin", {}},
        {"WorldEnd", {}},
        {"AttributeBegin", {}},
        {"AttributeEnd", {}},
        {"TransformBegin", {}},
        {"TransformEnd", {}},
        {"ObjectEnd", {}},
        {"ReverseOrientation", {}},
        {"NamedMaterial", {0, 1, false}},
        {"CoordinateSystem", {0, 1, false}},
        {"CoordSysTransform", {0, 1, false}},
        {"ObjectBegin", {0, 1, false}},
        {"ObjectInstance", {0, 1, false}},
        {"Include", {0, 1, false}},
        {"Import", {0, 1, false}},
        {"ColorSpace", {0, 1, false}},
        {"MediumInterface", {0, -1, false}},
        {"Camera", {0, 1, true}},
        {"Film", {0, 1, true}},
        {"Sampler", {0, 1, true}},
        {"Integrator", {0, 1, true}},
        {"PixelFilter", {0, 1, true}},
        {"Accelerator", {0, 1, true}},
        {"Shape", {0, 1, true}},
        {"Material", {0, 1, true}},
        {"MakeNamedMaterial", {0, 1, true}},
        {"LightSource", {0, 1, true}},
        {"AreaLightSource", {0, 1, true}},
        {"MakeNamedMedium", {0, 1, true}},
        {"Attribute", {0, 1, true}},
        {"Texture", {0, 3, true}},
        {"Option", {0, 0, true}},
        {"ActiveTransform", {}},
    };
    return table;
}

const std::set<std::string>& numeric_types() {
    static const std::set<std::string> types = {
        "integer", "float", "point2", "vector2", "point3", "vector3",  "normal",
        "normal3", "point", "vector", "color",   "rgb",    "blackbody"};
    return types;
}

const std::set<std::string>& string_types() {
    static const std::set<std::string> types = {"string", "texture"};
    return types;
}

class Parser {
   public:
    Parser(const std::filesystem::path& main, const SceneFiles& files)
        : dir_(main.parent_path()), files_(files) {}

    void parse(const std::filesystem::path& path, int depth, const std::string& included_at) {
        if (depth > kMaxIncludeDepth) {
            throw Error(included_at + ": Include nested deeper than " +
                        std::to_string(kMaxIncludeDepth) + " files (an include cycle?)");
        }
        if (++files_read_ > kMaxIncludedFiles) {
            throw Error(included_at + ": more than " + std::to_string(kMaxIncludedFiles) +
                        " included files");
        }
        if (!files_.exists(path)) {
            throw Error((included_at.empty()
                             ? path.string()
                             : included_at + ": Include " + excerpt(path.string())) +
                        ": file not found");
        }
        PbrtTokenizer tokens(files_.read(path, kMaxSceneFileBytes, "pbrt scene file"),
                             path.string());
        for (;;) {
            PbrtToken token = tokens.next();
            if (token.kind == PbrtTokenKind::kEnd) {
                return;
            }
            if (token.kind != PbrtTokenKind::kWord) {
                throw Error(tokens.where(token.line) + ": expected a directive, got " +
                            describe_token(token));
            }
            PbrtDirective directive = read_directive(tokens, token);
            if (directive.name == "Include" || directive.name == "Import") {
                parse(resolve(directive.strings[0]), depth + 1, directive.where());
            } else {
                directives_.push_back(std::move(directive));
            }
        }
    }

    std::vector<PbrtDirective> take() { return std::move(directives_); }

   private:
    // A relative path names a file in the main scene file's folder (pbrt's search directory).
    std::filesystem::path resolve(const std::string& name) const {
        const std::filesystem::path path(name);
        return path.is_absolute() ? path : dir_ / path;
    }

    PbrtDirective read_directive(PbrtTokenizer& tokens, const PbrtToken& word) {
        const auto grammar = grammars().find(word.text);
        if (grammar == grammars().end()) {
            throw Error(tokens.where(word.line) + ": unknown directive '" + excerpt(word.text) +
                        "'");
        }
        PbrtDirective directive;
        directive.name = word.text;
        directive.file = tokens.file();
        directive.line = word.line;
        if (directive.name == "ActiveTransform") {  // a bare word: StartTime, EndTime or All
            const PbrtToken which = tokens.next();
            if (which.kind != PbrtTokenKind::kWord) {
                throw Error(directive.where() +
                            ": ActiveTransform expects StartTime, EndTime or "
                            "All, got " +
                            describe_token(which));
            }
            directive.strings.push_back(which.text);
            return directive;
        }
        read_numbers(tokens, directive, grammar->second.numbers);
        const int strings = grammar->second.strings;
        for (int i = 0; i < (strings < 0 ? 2 : strings); ++i) {
            if (strings < 0 && i > 0 && tokens.peek().kind != PbrtTokenKind::kString) {
                break;
            }
            const PbrtToken token = tokens.next();
            if (token.kind != PbrtTokenKind::kString) {
                throw Error(directive.where() + ": " + directive.name + " expects a quoted " +
                            "string, got " + describe_token(token));
            }
            directive.strings.push_back(token.text);
        }
        while (grammar->second.params && tokens.peek().kind == PbrtTokenKind::kString) {
            directive.params.push_back(read_param(tokens, directive));
        }
        return directive;
    }

    void read_numbers(PbrtTokenizer& tokens, PbrtDirective& directive, int count) {
        if (count == 0) {
            return;
        }
        const bool bracketed = tokens.peek().kind == PbrtTokenKind::kOpenBracket;
        if (bracketed) {
            tokens.next();
        }
        for (int i = 0; i < count; ++i) {
            const PbrtToken token = tokens.next();
            if (token.kind != PbrtTokenKind::kNumber) {
                throw Error(directive.where() + ": " + directive.name + " expects " +
                            std::to_string(count) + " numbers, got " + describe_token(token));
            }
            directive.numbers.push_back(token.number);
        }
        if (bracketed) {
            const PbrtToken token = tokens.next();
            if (token.kind != PbrtTokenKind::kCloseBracket) {
                throw Error(directive.where() + ": " + directive.name + " expects ']' after " +
                            std::to_string(count) + " numbers, got " + describe_token(token));
            }
        }
    }

    // "type name" and its value: one literal or a bracketed list.
    PbrtParam read_param(PbrtTokenizer& tokens, const PbrtDirective& directive) {
        const PbrtToken declaration = tokens.next();
        const std::string where = tokens.where(declaration.line);
        PbrtParam param;
        const std::string& text = declaration.text;
        const size_t type_start = text.find_first_not_of(" \t");
        const size_t type_end = text.find_first_of(" \t", type_start);
        const size_t name_start = type_end == std::string::npos
                                      ? std::string::npos
                                      : text.find_first_not_of(" \t", type_end);
        const size_t name_end = name_start == std::string::npos
                                    ? std::string::npos
                                    : text.find_first_of(" \t", name_start);
        if (name_start == std::string::npos ||
            (name_end != std::string::npos &&
             text.find_first_not_of(" \t", name_end) != std::string::npos)) {
            throw Error(where + ": " + directive.name +
                        ": expected a parameter \"type name\", got \"" + excerpt(text) + "\"");
        }
        param.type = text.substr(type_start, type_end - type_start);
        param.name = text.substr(
            name_start, name_end == std::string::npos ? std::string::npos : name_end - name_start);
        const bool numeric = numeric_types().count(param.type) > 0;
        const bool textual = string_types().count(param.type) > 0;
        param.is_bool = param.type == "bool";
        if (!numeric && !textual && !param.is_bool && param.type != "spectrum") {
            throw Error(where + ": " + directive.name + ": unknown parameter type '" +
                        excerpt(param.type) + "' in \"" + excerpt(text) + "\"");
        }
        const bool bracketed = tokens.peek().kind == PbrtTokenKind::kOpenBracket;
        if (bracketed) {
            tokens.next();
        }
        for (;;) {
            const PbrtTokenKind kind = tokens.peek().kind;
            if (bracketed && kind == PbrtTokenKind::kCloseBracket) {
                tokens.next();
                break;
            }
            if (kind == PbrtTokenKind::kNumber) {
                param.numbers.push_back(tokens.next().number);
            } else if (kind == PbrtTokenKind::kString ||
                       (param.is_bool && kind == PbrtTokenKind::kWord)) {
                param.strings.push_back(tokens.next().text);
            } else {
                throw Error(where + ": " + directive.name + ": parameter \"" + excerpt(text) +
                            "\": expected " + (bracketed ? "a value or ']'" : "a value") +
                            ", got " + describe_token(tokens.peek()));
            }
            if (!bracketed) {
                break;
            }
        }
        check_value_types(param,
                          where + ": " + directive.name + ": parameter \"" + excerpt(text) + "\"");
        return param;
    }

    static void check_value_types(const PbrtParam& param, const std::string& what) {
        if (param.numbers.empty() && param.strings.empty()) {
            throw Error(what + ": has no value");
        }
        if (!param.numbers.empty() && !param.strings.empty()) {
            throw Error(what + ": mixes numbers and strings");
        }
        const bool numeric = numeric_types().count(param.type) > 0;
        if (numeric && !param.strings.empty()) {
            throw Error(what + ": expected numbers, got a string");
        }
        if ((string_types().count(param.type) > 0 || param.is_bool) && !param.numbers.empty()) {
            throw Error(what + ": expected " + (param.is_bool ? "true or false" : "strings") +
                        ", got a number");
        }
        if (param.is_bool) {
            for (const std::string& value : param.strings) {
                if (value != "true" && value != "false") {
                    throw Error(what + ": expected true or false, got \"" + excerpt(value) + "\"");
                }
            }
        }
        if (param.type == "integer") {
            for (double value : param.numbers) {
                if (std::abs(value) > 2147483647.0 || value != std::floor(value)) {
                    throw Error(what + ": " + excerpt(std::to_string(value)) +
                                " is not a 32-bit integer");
                }
            }
        }
    }

    std::filesystem::path dir_;
    const SceneFiles& files_;
    std::vector<PbrtDirective> directives_;
    int files_read_ = 0;
};

}  // namespace

std::vector<PbrtDirective> parse_pbrt_file(const std::filesystem::path& path,
                                           const SceneFiles& files) {
    Parser parser(path, files);
    parser.parse(path, 0, "");
    return parser.take();
}

}  // namespace rc
