// A PLY file's header, checked before scene/ply_mesh.h reads the body: the header printable text,
// well formed, with element counts the file's size can hold and, for ASCII files, a body of only
// numbers and blanks. (These checks began as guards for Assimp 5.2's PLY reader, which loops
// without end on a 74-byte file without end_header, an ASCII body with NUL bytes or a vertical
// tab in the header: found by the pbrt fuzz target, tests/fuzz/regressions/pbrt/.)
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rc {

// One property of a PLY element: a scalar of `type`, or (count_type not empty) a list of `type`
// values after a count of count_type. Types are PLY's names (char, uchar, ..., float64).
struct PlyProperty {
    std::string name;
    std::string type;
    std::string count_type;
};

struct PlyElement {
    std::string name;
    size_t count = 0;
    std::vector<PlyProperty> properties;
};

enum class PlyFormat { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

// A header check_ply_header accepted: the elements in file order and where the body starts.
struct PlyHeader {
    PlyFormat format = PlyFormat::kAscii;
    std::vector<PlyElement> elements;
    size_t body = 0;
};

// Error naming `what` unless `bytes` starts with a well-formed PLY header (ply, format ascii or
// binary 1.0, elements with counts, scalar or list properties of PLY's types, end_header) that
// declares a "vertex" element with x, y and z and a "face" element with a vertex_indices (or
// vertex_index) list, and whose elements fit in the bytes after the header (binary: at least
// their fixed size; ASCII: at least two bytes per value, and nothing but digits, signs, points,
// exponents and blanks), walking the body so that every list's count fits in what is left of the
// file (a count of 2^30 indices is refused before any reader allocates for it) and a file that
// ends inside an element is named as truncated. Returns the header.
PlyHeader check_ply_header(const std::string& bytes, const std::string& what);

}  // namespace rc
