#include "scene/ply_header.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <sstream>
#include <vector>

#include "util/error.h"
#include "util/text.h"

namespace rc {
namespace {

// The limits of a header radcache reads: its length, and an element's count.
constexpr size_t kMaxHeaderBytes = 1 << 16;
constexpr double kMaxElementCount = 2147483647.0;

// The size in bytes of a PLY scalar type, or 0 for a name that is none.
size_t type_size(const std::string& type) {
    static const std::map<std::string, size_t> sizes = {
        {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
        {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
        {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
    const auto found = sizes.find(type);
    return found == sizes.end() ? 0 : found->second;
}

bool is_name(const std::string& word) {
    if (word.empty()) {
        return false;
    }
    for (char c : word) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') {
            return false;
        }
    }
    return true;
}

// A property's layout: a scalar of `size` bytes, or a list whose count takes count_size bytes
// (signed where count_signed) before `size`-byte items.
struct Property {
    size_t size = 0;
    size_t count_size = 0;  // 0: a scalar
    bool count_signed = false;
};

struct Element {
    std::string name;
    double count = 0;
    size_t fixed_bytes = 0;  // binary: scalars plus each list's count
    size_t values = 0;       // scalars and lists
    std::vector<std::string> properties;
    std::vector<Property> layout;
    std::vector<PlyProperty> declared;  // as the header names them
};

bool is_signed(const std::string& type) {
    return type == "char" || type == "int8" || type == "short" || type == "int16" ||
           type == "int" || type == "int32";
}

// A binary list count of `p` at `at` (its bytes in the file's byte order), as a number.
double binary_count(const std::string& bytes, size_t at, const Property& p, bool big_endian) {
    uint64_t raw = 0;
    for (size_t k = 0; k < p.count_size; ++k) {
        const size_t byte = big_endian ? k : p.count_size - 1 - k;
        raw = (raw << 8) | static_cast<unsigned char>(bytes[at + byte]);
    }
    if (p.count_signed && (raw >> (8 * p.count_size - 1)) != 0) {
        return -1.0;  // negative
    }
    return static_cast<double>(raw);
}

// Every element of a binary body walked: each list's count read and bounded by the bytes left,
// so a count the file cannot hold (2^30 indices) is refused before a reader allocates for it, and
// a file that ends inside an element is named as truncated.
template <class Fail>
void walk_binary_body(const std::string& bytes, size_t at, const std::vector<Element>& elements,
                      bool big_endian, const Fail& fail) {
    for (const Element& e : elements) {
        for (double i = 0; i < e.count; ++i) {
            for (const Property& p : e.layout) {
                const auto where = [&] {
                    return "element " + e.name + " " + std::to_string(static_cast<long long>(i));
                };
                if (p.count_size > bytes.size() - at) {
                    fail(where() + " runs past the end of the file (truncated?)");
                }
                double items = 1.0;
                if (p.count_size > 0) {
                    items = binary_count(bytes, at, p, big_endian);
                    at += p.count_size;
                    if (items < 0.0) {
                        fail(where() + ": a list of a negative count");
                    }
                }
                if (items * static_cast<double>(p.size) > static_cast<double>(bytes.size() - at)) {
                    fail(where() + ": " +
                         (p.count_size > 0
                              ? "a list of " + std::to_string(static_cast<long long>(items)) +
                                    " values runs past the end of the file"
                              : std::string("runs past the end of the file (truncated?)")));
                }
                at += static_cast<size_t>(items) * p.size;
            }
        }
    }
}

// The same for an ASCII body: every list's count a whole number no larger than the values left.
template <class Fail>
void walk_ascii_body(const std::string& bytes, size_t body, const std::vector<Element>& elements,
                     const Fail& fail) {
    size_t at = body;
    // Moves `at` past the next word of the body; its first byte's offset, or npos at the end.
    const auto next_word = [&]() {
        while (at < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[at]))) {
            ++at;
        }
        const size_t start = at;
        while (at < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[at]))) {
            ++at;
        }
        return start < bytes.size() ? start : std::string::npos;
    };
    double left = 0.0;  // the words of the body not yet read
    while (next_word() != std::string::npos) {
        left += 1.0;
    }
    at = body;
    for (const Element& e : elements) {
        for (double i = 0; i < e.count; ++i) {
            for (const Property& p : e.layout) {
                const auto where = [&] {
                    return "element " + e.name + " " + std::to_string(static_cast<long long>(i));
                };
                if (left < 1.0) {
                    fail(where() + " runs past the end of the file (truncated?)");
                }
                const size_t word = next_word();
                left -= 1.0;
                if (p.count_size == 0) {
                    continue;
                }
                const double value = std::strtod(bytes.c_str() + word, nullptr);
                if (!(value >= 0.0) || value != std::floor(value) || value > left) {
                    const bool whole = value == std::floor(value) && std::fabs(value) < 1e15;
                    fail(where() + ": a list count of " +
                         (whole ? std::to_string(static_cast<long long>(value))
                                : excerpt(std::to_string(value))) +
                         " with " + std::to_string(static_cast<long long>(left)) +
                         " values left in the file");
                }
                for (double k = 0; k < value; ++k) {
                    next_word();
                }
                left -= value;
            }
        }
    }
}

}  // namespace

PlyHeader check_ply_header(const std::string& bytes, const std::string& what) {
    const auto fail = [&](const std::string& message) {
        throw Error(what + ": not a readable PLY file: " + message);
    };
    size_t end = bytes.find("\nend_header");
    if (bytes.compare(0, 3, "ply") != 0 || end == std::string::npos || end > kMaxHeaderBytes) {
        fail("no \"ply\" ... \"end_header\" header");
    }
    ++end;  // the start of the end_header line
    // Printable text, blanks and line ends only (Assimp's reader loops without end on a
    // vertical tab in the header).
    for (size_t i = 0; i < end; ++i) {
        const unsigned char c = static_cast<unsigned char>(bytes[i]);
        if (!(c >= 0x20 && c < 0x7f) && c != '\t' && c != '\r' && c != '\n') {
            fail("a byte " + std::to_string(c) + " in the header at offset " + std::to_string(i));
        }
    }
    size_t body = end + std::string("end_header").size();
    if (bytes.compare(body, 1, "\n") == 0) {
        body += 1;
    } else if (bytes.compare(body, 2, "\r\n") == 0) {
        body += 2;
    } else if (body != bytes.size()) {
        fail("\"end_header\" is not followed by the end of its line");
    }
    std::istringstream header(bytes.substr(0, end));
    std::string line;
    std::getline(header, line);
    std::string format;
    std::vector<Element> elements;
    while (std::getline(header, line)) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword.empty() || keyword == "comment" || keyword == "obj_info") {
            continue;
        }
        std::vector<std::string> rest;
        for (std::string word; words >> word;) {
            rest.push_back(word);
        }
        if (keyword == "format" && format.empty() && rest.size() == 2 && rest[1] == "1.0" &&
            (rest[0] == "ascii" || rest[0] == "binary_little_endian" ||
             rest[0] == "binary_big_endian")) {
            format = rest[0];
        } else if (keyword == "element" && rest.size() == 2 && is_name(rest[0]) &&
                   rest[1].find_first_not_of("0123456789") == std::string::npos &&
                   rest[1].size() <= 10 && std::stod(rest[1]) <= kMaxElementCount) {
            elements.push_back({rest[0], std::stod(rest[1])});
        } else if (keyword == "property" && !elements.empty() && rest.size() == 2 &&
                   type_size(rest[0]) > 0 && is_name(rest[1])) {
            elements.back().fixed_bytes += type_size(rest[0]);
            ++elements.back().values;
            elements.back().properties.push_back(rest[1]);
            elements.back().layout.push_back({type_size(rest[0]), 0, false});
            elements.back().declared.push_back({rest[1], rest[0], ""});
        } else if (keyword == "property" && !elements.empty() && rest.size() == 4 &&
                   rest[0] == "list" && type_size(rest[1]) > 0 && rest[1] != "float" &&
                   rest[1] != "double" && rest[1] != "float32" && rest[1] != "float64" &&
                   type_size(rest[2]) > 0 && is_name(rest[3])) {
            elements.back().fixed_bytes += type_size(rest[1]);
            ++elements.back().values;
            elements.back().properties.push_back(rest[3]);
            elements.back().layout.push_back(
                {type_size(rest[2]), type_size(rest[1]), is_signed(rest[1])});
            elements.back().declared.push_back({rest[3], rest[2], rest[1]});
        } else {
            fail("malformed header line \"" + excerpt(line) + "\"");
        }
    }
    if (format.empty()) {
        fail("no \"format ascii|binary_little_endian|binary_big_endian 1.0\" line");
    }
    if (format == "ascii") {
        // Digits, signs, points and exponents, separated by blanks: nothing else (a NUL or
        // another control byte in the body sends Assimp's reader into an endless loop).
        for (size_t i = body; i < bytes.size(); ++i) {
            const unsigned char c = static_cast<unsigned char>(bytes[i]);
            if (!std::isdigit(c) && c != '.' && c != '-' && c != '+' && c != 'e' && c != 'E' &&
                c != ' ' && c != '\t' && c != '\r' && c != '\n') {
                fail("a byte " + std::to_string(c) + " that is no part of a number at offset " +
                     std::to_string(i));
            }
        }
    }
    const auto has = [](const Element& e, const std::string& property) {
        for (const std::string& p : e.properties) {
            if (p == property) {
                return true;
            }
        }
        return false;
    };
    bool vertices = false;
    bool faces = false;
    double need = 0.0;
    for (const Element& e : elements) {
        vertices |= e.name == "vertex" && has(e, "x") && has(e, "y") && has(e, "z");
        faces |= e.name == "face" && (has(e, "vertex_indices") || has(e, "vertex_index"));
        need += e.count * static_cast<double>(format == "ascii" ? 2 * e.values : e.fixed_bytes);
    }
    if (!vertices || !faces) {
        fail("no \"vertex\" element with x, y, z, or no \"face\" element with vertex_indices");
    }
    if (format == "ascii" && need > 0.0) {
        need -= 1.0;  // the last value needs no separator after it
    }
    if (need > static_cast<double>(bytes.size() - body)) {
        fail("its elements need at least " + std::to_string(static_cast<long long>(need)) +
             " bytes, the file has " + std::to_string(bytes.size() - body) + " after its header");
    }
    if (format == "ascii") {
        walk_ascii_body(bytes, body, elements, fail);
    } else {
        walk_binary_body(bytes, body, elements, format == "binary_big_endian", fail);
    }
    PlyHeader result;
    result.format = format == "ascii"                  ? PlyFormat::kAscii
                    : format == "binary_little_endian" ? PlyFormat::kBinaryLittleEndian
                                                       : PlyFormat::kBinaryBigEndian;
    result.body = body;
    for (const Element& e : elements) {
        result.elements.push_back({e.name, static_cast<size_t>(e.count), e.declared});
    }
    return result;
}

}  // namespace rc
