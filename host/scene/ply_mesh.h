// A PLY mesh (Greg Turk's format, as pbrt-v4's "plymesh" reads it): the vertex element's x, y, z
// and, when present, nx, ny, nz and u, v (or s, t, texture_u, texture_v, texture_s, texture_t),
// and the face element's vertex_indices (or vertex_index) lists of 3 or 4 indices. Read by
// radcache from the header scene/ply_header.h checks and the body it walks, in ASCII and in
// either binary byte order (Assimp 5.2, which read these before, misreads a binary body whose
// first byte is 0x0a, a line feed).
#pragma once

#include <string>

#include "scene/triangle_mesh.h"

namespace rc {

// The triangles (and normals and uvs) of a PLY file (a quad split along its 0-2 diagonal,
// warned about when not planar); Error naming `what` for an unreadable or malformed file: a
// face of another size, an index out of range, a coordinate that is not finite.
TriangleMesh load_ply_mesh(const std::string& bytes, const std::string& what);

}  // namespace rc
