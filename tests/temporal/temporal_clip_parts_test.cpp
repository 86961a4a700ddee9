// A temporal clip rendered in parts, as the farm splits it (docs/farm.md): a part of frames a..b
// with the clip's frames before it as warm-up (--write-from a) and the clip's end named
// (--clip-end) gives every one of its frames bitwise as one process rendering the whole clip,
// with each record cache (ic, rc, sdrc) and the default interpolated temporal gradients, which
// place records ahead of the frame they shade. Without --clip-end a part's last frame differs:
// its records were placed as if the clip ended there.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/image.h"
#include "image/image_io.h"
#include "test_support.h"

namespace rc {
namespace {

std::string moving_sphere() {
    return (test::source_dir() / "scenes" / "moving-sphere" / "scene.json").string();
}

// `radcache render` of the moving sphere with `method` --temporal, 16 x 16, 1 spp, and `more`,
// into dir/name.####.exr.
void render(const std::filesystem::path& dir, const std::string& name, const std::string& method,
            const std::vector<std::string>& more) {
    std::vector<std::string> args = {"render",     moving_sphere(),
                                     "--method",   method,
                                     "--temporal", "--width",
                                     "16",         "--height",
                                     "16",         "--spp",
                                     "1",          "--ic-rays",
                                     "32",         "-q",
                                     "-o",         (dir / (name + ".####.exr")).string()};
    args.insert(args.end(), more.begin(), more.end());
    const test::CommandResult result = test::run_radcache(args);
    ASSERT_EQ(result.exit_code, 0) << result.output;
}

std::vector<float> frame_pixels(const std::filesystem::path& dir, const std::string& name,
                                int frame) {
    char file[64];
    std::snprintf(file, sizeof file, "%s.%04d.exr", name.c_str(), frame);
    return read_image(dir / file).pixels;
}

TEST(TemporalClipParts, PartsWithWarmUpAndTheClipsEndAreOneProcesssFrames) {
    for (const char* method : {"ic", "rc", "sdrc"}) {
        SCOPED_TRACE(method);
        const auto dir = test::scratch_dir(std::string("clip_parts_") + method);
        render(dir, "one", method, {"--frames", "0:3"});
        render(dir, "first", method, {"--frames", "0:1", "--clip-end", "3"});
        render(dir, "second", method, {"--frames", "0:3", "--write-from", "2"});
        render(dir, "cut", method, {"--frames", "0:1"});
        for (int frame = 0; frame < 4; ++frame) {
            EXPECT_EQ(frame_pixels(dir, frame < 2 ? "first" : "second", frame),
                      frame_pixels(dir, "one", frame))
                << "frame " << frame;
        }
        EXPECT_NE(frame_pixels(dir, "cut", 1), frame_pixels(dir, "one", 1))
            << "a part without --clip-end: its last frame's records are placed as at a clip's end";
    }
}

}  // namespace
}  // namespace rc
