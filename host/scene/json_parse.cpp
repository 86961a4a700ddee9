#include "scene/json_parse.h"

#include <algorithm>
#include <vector>

#include "util/error.h"
#include "util/text.h"

namespace rc {
namespace {

using Json = nlohmann::json;

// nlohmann's SAX events to a Json document, like its own DOM builder, with three checks it does
// not make: the nesting depth, keys given twice, and (through parse_error) the file and position
// of every error.
class StrictDomBuilder {
   public:
    StrictDomBuilder(const std::string& text, const std::string& file) : text_(text), file_(file) {}

    Json take() { return std::move(root_); }

    bool null() { return add(Json(nullptr)); }
    bool boolean(bool value) { return add(Json(value)); }
    bool number_integer(Json::number_integer_t value) { return add(Json(value)); }
    bool number_unsigned(Json::number_unsigned_t value) { return add(Json(value)); }
    bool number_float(Json::number_float_t value, const Json::string_t&) {
        return add(Json(value));
    }
    bool string(Json::string_t& value) { return add(Json(std::move(value))); }
    bool binary(Json::binary_t& value) { return add(Json::binary(std::move(value))); }

    bool start_object(std::size_t) { return open(Json::object()); }
    bool start_array(std::size_t) { return open(Json::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(Json::string_t& key) {
        Json& object = *open_.back();
        if (object.contains(key)) {
            throw Error(file_ + ": " + path_to(excerpt(key)) + ": key given twice in one object");
        }
        names_.back() = key;
        pending_ = &object[key];
        return true;
    }

    bool parse_error(std::size_t position, const std::string&,
                     const nlohmann::detail::exception& error) {
        // nlohmann's message reads "[json.exception.parse_error.101] parse error at line L,
        // column C: ..."; keep the part after the bracketed id, and give the position where the
        // message has none (a number out of range).
        std::string message = error.what();
        if (const size_t close = message.find("] "); close != std::string::npos) {
            message = message.substr(close + 2);
        }
        if (message.find(" at line ") == std::string::npos) {
            message = "at " + line_and_column(position) + ": " + message;
        }
        throw Error(file_ + ": malformed JSON: " + excerpt(message, 2 * kQuoteLimit));
    }

   private:
    // Places a value: the root, the next array item, or the value of the last key.
    bool add(Json value) {
        place(std::move(value));
        return true;
    }

    Json* place(Json value) {
        if (open_.empty()) {
            root_ = std::move(value);
            return &root_;
        }
        Json& container = *open_.back();
        if (container.is_array()) {
            names_.back() = "[" + std::to_string(container.size()) + "]";
            container.push_back(std::move(value));
            return &container.back();
        }
        *pending_ = std::move(value);
        return pending_;
    }

    bool open(Json container) {
        if (open_.size() >= static_cast<size_t>(kMaxJsonDepth)) {
            throw Error(file_ + ": " + path_to("") + ": nested deeper than " +
                        std::to_string(kMaxJsonDepth) + " levels");
        }
        Json* placed = place(std::move(container));
        open_.push_back(placed);
        names_.emplace_back();
        return true;
    }

    bool close() {
        open_.pop_back();
        names_.pop_back();
        return true;
    }

    // The key path of the open containers, then `last` ("camera.fov", "shapes[2].file").
    std::string path_to(const std::string& last) const {
        std::string path;
        for (size_t i = 0; i + 1 < names_.size(); ++i) {
            const std::string& name = names_[i];
            path += (path.empty() || name.front() == '[' ? "" : ".") + excerpt(name);
        }
        if (!last.empty()) {
            path += (path.empty() ? "" : ".") + last;
        }
        if (path.size() > 2 * kQuoteLimit) {
            path = path.substr(0, 2 * kQuoteLimit - 3) + "...";
        }
        return path.empty() ? "top level" : path;
    }

    std::string line_and_column(size_t position) const {
        size_t line = 1;
        size_t column = 1;
        for (size_t i = 0; i < position && i < text_.size(); ++i) {
            if (text_[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        return "line " + std::to_string(line) + ", column " + std::to_string(column);
    }

    const std::string& text_;
    const std::string& file_;
    Json root_;
    std::vector<Json*> open_;         // the containers being filled, outermost first
    std::vector<std::string> names_;  // per open container: its current key or [index]
    Json* pending_ = nullptr;         // where the value of the last key goes
};

// Appends at most about `budget` characters of `value` to `out`.
void append_bounded(const Json& value, std::string& out, size_t budget, int depth) {
    if (out.size() > budget) {
        return;
    }
    if (value.is_string()) {
        out += "\"" + excerpt(value.get_ref<const std::string&>(), budget) + "\"";
    } else if (value.is_object() || value.is_array()) {
        const bool object = value.is_object();
        out += object ? "{" : "[";
        if (depth > 8 && !value.empty()) {
            out += "...";
        } else {
            bool first = true;
            for (auto item = value.begin(); item != value.end() && out.size() <= budget; ++item) {
                out += first ? "" : ",";
                first = false;
                if (object) {
                    out += "\"" + excerpt(item.key(), budget) + "\":";
                }
                append_bounded(item.value(), out, budget, depth + 1);
            }
        }
        out += object ? "}" : "]";
    } else if (value.is_binary()) {
        out += "<binary>";
    } else {
        out += value.dump();
    }
}

}  // namespace

Json parse_json(const std::string& text, const std::string& file) {
    StrictDomBuilder builder(text, file);
    Json::sax_parse(text, &builder, Json::input_format_t::json, /*strict=*/true,
                    /*ignore_comments=*/true);
    return builder.take();
}

std::string describe_json(const Json& value) {
    std::string text;
    append_bounded(value, text, kQuoteLimit, 0);
    if (text.size() > kQuoteLimit) {
        text = text.substr(0, kQuoteLimit - 3) + "...";
    }
    return text;
}

int json_nesting_depth(std::string_view text) {
    int depth = 0;
    int deepest = 0;
    bool in_string = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') {
                ++i;  // the escaped character, a quote included
            } else if (c == '"') {
                in_string = false;
            }
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

}  // namespace rc
