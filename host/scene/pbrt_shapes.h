// The triangles of pbrt-v4's shapes (docs/importing.md#pbrt-v4-import): "trianglemesh"
// (P, indices, N, uv), "bilinearmesh" (each planar patch as two triangles), "plymesh"
// (scene/ply_mesh.h), "sphere", "disk" and "cylinder" (tessellated: scene/shapes/), in object
// space. Errors name the directive.
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

}  // namespace rc
