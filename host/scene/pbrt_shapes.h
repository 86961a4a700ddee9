// The triangles of pbrt-v4's shapes (docs/importing.md#pbrt-v4-import): "trianglemesh"
// (P, indices, N, uv), "bilinearmesh" (each planar patch as two triangles), "plymesh" (read
// through Assimp) and "sphere" (tessellated), in object space. Errors name the directive.
#pragma once

#include <filesystem>

#include "scene/pbrt_params.h"
#include "scene/scene_files.h"
#include "scene/triangle_mesh.h"

namespace rc {

// The triangles of the shape `type` from its parameters; `dir` resolves a plymesh's relative
// filename. A non-planar bilinear patch or quad, and a tessellated sphere, are warned about.
TriangleMesh pbrt_shape_mesh(const std::string& type, PbrtParams& params,
                             const std::filesystem::path& dir, const SceneFiles& files);

// Whether pbrt_shape_mesh knows the shape type.
bool is_pbrt_shape_supported(const std::string& type);

// The triangles (and normals and uvs) of a PLY file's "vertex" and "face" elements (triangles
// and quads; a quad split along its 0-2 diagonal, warned about when not planar); Error naming
// `what` for an unreadable or malformed file.
TriangleMesh load_ply_mesh(const std::string& bytes, const std::string& what);

}  // namespace rc
