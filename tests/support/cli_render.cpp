#include "cli_render.h"

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "test_support.h"

namespace rc::test {

Image render_scene_file(const std::filesystem::path& scene, const std::filesystem::path& out,
                        const std::vector<std::string>& options) {
    std::vector<std::string> args = {"render", scene.string(), "-o", out.string(), "--spp",
                                     "4",      "--quiet"};
    args.insert(args.end(), options.begin(), options.end());
    const CommandResult result = run_radcache(args);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return read_image(out);
}

}  // namespace rc::test
