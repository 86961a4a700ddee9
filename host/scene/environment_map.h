// An environment map's light on the host (kernels/common/environment_map.h samples and reads
// it): its sampling distribution, its mean radiance and the bound on a photon's flux.
#pragma once

#include <vector>

#include "scene/emitter.h"
#include "scene/scene.h"
#include "scene/texture.h"
#include "shared/types.h"

namespace rc {

// Fills the map fields of `light` (the constant environment of `emitter`, whose map is
// `texture`): the texture, mapping and frame; appends the map's distribution to `cdf` (its rows'
// cumulative weights, then each row's; a texel's weight its mean channel times the solid angle
// its image area covers, so that directions are drawn in proportion to radiance); light.radiance
// becomes the map's mean radiance over the sphere and light.area the largest ratio of a channel's
// radiance to the solid-angle density of its direction (the photon flux bound). Returns the
// map's mean radiance. Error when the map gives no light anywhere.
glm::vec3 add_environment_map(const Emitter& emitter, const Texture& texture,
                              std::vector<float>& cdf, shared::Light& light);

// Makes `emitter` the constant environment of the image `file` (read through `files`, linear
// RGB) times `scale` in `mapping`, the image added to scene.textures. Error naming the file for
// an unreadable image, or an equal-area map that is not square.
void load_environment_map(Scene& scene, Emitter& emitter, const std::filesystem::path& file,
                          const SceneFiles& files, glm::vec3 scale, int mapping);

// The mapping's name (latlong, equal-area) as the JSON format spells it, and back (-1: none).
const char* map_mapping_name(int mapping);
int map_mapping_of(const std::string& name);

}  // namespace rc
