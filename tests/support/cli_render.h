// Rendering a scene file through the command line, as the scene-format tests compare them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/image.h"

namespace rc::test {

// `radcache render scene -o out --spp 4 --quiet` with `options` after, which must succeed (a
// failed expectation otherwise): the image it wrote.
Image render_scene_file(const std::filesystem::path& scene, const std::filesystem::path& out,
                        const std::vector<std::string>& options);

}  // namespace rc::test
