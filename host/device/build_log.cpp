#include "device/build_log.h"

#include <regex>
#include <set>
#include <sstream>
#include <vector>

namespace rc {
namespace {

const std::regex& line_marker() {
    static const std::regex marker(R"(^\s*#\s*line\s+(\d+)\s+"([^"]+)\".*$)");
    return marker;
}

// Per expanded line (index line - 1): its file ("" before the first marker) and line there.
struct LineMap {
    std::vector<std::string> files;
    std::vector<long> lines;
    std::set<std::string> names;  // every file a marker names
};

LineMap line_map(const std::string& source) {
    LineMap map;
    std::istringstream text(source);
    std::string line;
    std::string file;
    long next = 0;  // the original line number of the next expanded line
    while (std::getline(text, line)) {
        std::smatch match;
        map.files.push_back(file);
        map.lines.push_back(next);
        if (std::regex_match(line, match, line_marker())) {
            file = match[2].str();
            next = std::stol(match[1].str());
            map.names.insert(file);
        } else {
            ++next;
        }
    }
    return map;
}

// Where expanded line `line` (1-based) came from, as "file:line"; the plain number when no
// marker precedes it or it is out of range.
std::string location(const LineMap& map, long line) {
    if (line < 1 || static_cast<size_t>(line) > map.files.size() ||
        map.files[static_cast<size_t>(line - 1)].empty()) {
        return std::to_string(line);
    }
    const size_t i = static_cast<size_t>(line - 1);
    return map.files[i] + ":" + std::to_string(map.lines[i]);
}

}  // namespace

std::string map_build_log(const std::string& log, const std::string& source) {
    const LineMap map = line_map(source);
    // NAME:LINE:COL: (clang-style: PoCL, NVIDIA, Intel) and "NAME", line LINE: (EDG-style: AMD).
    static const std::regex colon_form(R"(^([^:\s]*):(\d+):(\d+):(.*)$)");
    static const std::regex quoted_form(R"re(^"([^"]*)", line (\d+):(.*)$)re");
    std::istringstream lines(log);
    std::string out;
    std::string line;
    while (std::getline(lines, line)) {
        std::smatch match;
        if (std::regex_match(line, match, colon_form) && map.names.count(match[1].str()) == 0) {
            const long number = std::stol(match[2].str());
            line = location(map, number) + ":" + match[3].str() + ":" + match[4].str();
        } else if (std::regex_match(line, match, quoted_form) &&
                   map.names.count(match[1].str()) == 0) {
            const long number = std::stol(match[2].str());
            line = location(map, number) + ":" + match[3].str();
        }
        if (!out.empty()) {
            out += "\n";
        }
        out += line;
    }
    return out;
}

}  // namespace rc
