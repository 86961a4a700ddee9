// Reads a pbrt-v4 scene (.pbrt, with the files it includes, its PLY meshes and image textures)
// into a radcache scene (docs/importing.md#pbrt-v4-import): the graphics state (the current
// transform, attributes, named coordinate systems, materials, area lights, object instances)
// is followed directive by directive; the camera, film, sampler, integrator and pixel filter
// become the scene's camera and render defaults. A directive or parameter radcache cannot
// honour is an Error or a warning naming "file:line" (warnings are errors under --strict).
//
// pbrt's camera space is left-handed: with the same LookAt, pbrt's image is the mirror of
// radcache's. The import keeps pbrt's image: when the camera transform does not itself mirror,
// the world is mirrored about the camera's vertical plane (which mirrors the image back).
#pragma once

#include <filesystem>

#include "scene/pbrt_parser.h"
#include "scene/scene.h"
#include "scene/scene_files.h"

namespace rc {

// Loads the pbrt-v4 file; the scene is posed at frame 0.
Scene load_pbrt_scene(const std::filesystem::path& path, const SceneFiles& files);

}  // namespace rc
