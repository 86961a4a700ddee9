// Every shipped scene loads and renders without NaN, and every shipped reference matches its
// scene (resolution, layers, a record of how it was made).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::vector<std::filesystem::path> shipped_scenes() {
    std::vector<std::filesystem::path> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(test::source_dir() / "scenes")) {
        if (std::filesystem::is_regular_file(entry.path() / "scene.json")) {
            scenes.push_back(entry.path());
        }
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

TEST(Scenes, EveryShippedSceneRendersWithoutNonFiniteSamples) {
    const auto dir = test::scratch_dir("shipped_scenes");
    const auto scenes = shipped_scenes();
    EXPECT_GE(scenes.size(), 5u);
    for (const std::filesystem::path& folder : scenes) {
        SCOPED_TRACE(folder.filename().string());
        const auto output = dir / (folder.filename().string() + ".exr");
        const auto stats = dir / (folder.filename().string() + ".json");
        const test::CommandResult result = test::run_radcache(
            {"render", (folder / "scene.json").string(), "-o", output.string(), "--spp", "2",
             "--width", "12", "--height", "12", "--quiet", "--stats", stats.string()});
        ASSERT_EQ(result.exit_code, 0) << result.output;
        EXPECT_EQ(nlohmann::json::parse(read_file(stats))["nonfinite_samples"], 0);
        const Image image = read_image(output);
        double sum = 0.0;
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                sum += image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2);
            }
        }
        EXPECT_GT(sum, 0.0) << "a black image";
    }
}

TEST(Scenes, ReferencesMatchTheirScenes) {
    size_t references = 0;
    for (const std::filesystem::path& folder : shipped_scenes()) {
        if (!std::filesystem::exists(folder / "reference.exr")) {
            continue;
        }
        SCOPED_TRACE(folder.filename().string());
        ++references;
        const Scene scene = load_scene(folder / "scene.json");
        const nlohmann::json record = nlohmann::json::parse(read_file(folder / "reference.json"));
        const Image reference = read_image(folder / "reference.exr");
        EXPECT_EQ(reference.width, scene.camera.width);
        EXPECT_EQ(reference.height, scene.camera.height);
        EXPECT_EQ(record["resolution"][0], scene.camera.width);
        EXPECT_EQ(record["frame"], scene.animation.frame_start);
        EXPECT_EQ(record["nonfinite_samples"], 0);
        EXPECT_GE(record["spp"].get<int>(), 1024);
        EXPECT_EQ(layer_names(reference),
                  (std::vector<std::string>{"beauty", "direct", "indirect", "stddev"}));
    }
    // Every scene but the analytic furnace has one.
    EXPECT_EQ(references, shipped_scenes().size() - 1);
}

}  // namespace
}  // namespace rc
