// A PLY file's header, checked before Assimp reads the file (scene/pbrt_shapes.h): Assimp 5.2's
// PLY reader loops without end on some malformed files (a 74-byte file without end_header, an
// ASCII body with NUL bytes, a vertical tab in the header: found by the pbrt fuzz target,
// tests/fuzz/regressions/pbrt/), so radcache hands it only files whose header is printable text,
// well formed, with element counts the file's size can hold and, for ASCII files, whose body
// holds only numbers and blanks.
#pragma once

#include <string>

namespace rc {

// Error naming `what` unless `bytes` starts with a well-formed PLY header (ply, format ascii or
// binary 1.0, elements with counts, scalar or list properties of PLY's types, end_header) that
// declares a "vertex" element with x, y and z and a "face" element with a vertex_indices (or
// vertex_index) list, and whose elements fit in the bytes after the header (binary: at least
// their fixed size; ASCII: at least two bytes per value, and nothing but digits, signs, points,
// exponents and blanks), walking the body so that every list's count fits in what is left of the
// file (a count of 2^30 indices is refused before any reader allocates for it) and a file that
// ends inside an element is named as truncated.
void check_ply_header(const std::string& bytes, const std::string& what);

}  // namespace rc
