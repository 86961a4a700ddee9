// Every shipped scene loads and renders without NaN, and every shipped reference (every frame of
// an animated scene) matches its scene (resolution, layers, a record of how it was made).
#include <gtest/gtest.h>

#include <cstdio>
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

std::filesystem::path frame_reference(const std::filesystem::path& folder, int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame%04d.exr", frame);
    return folder / "reference" / name;
}

// The reference EXRs of a scene and their frames, by the layout of scenes/README.md: a still
// scene's reference.exr, or reference/frameFFFF.exr for every frame of an animated one, or every
// K-th frame from its first (K: from the first to the next frame that has one).
std::vector<std::pair<std::filesystem::path, int>> reference_files(
    const std::filesystem::path& folder, const Scene& scene) {
    const int first = static_cast<int>(scene.animation.frame_start);
    const int last = static_cast<int>(scene.animation.frame_end);
    if (last == first) {
        return {{folder / "reference.exr", first}};
    }
    int step = 1;
    while (first + step < last && !std::filesystem::exists(frame_reference(folder, first + step))) {
        ++step;
    }
    std::vector<std::pair<std::filesystem::path, int>> files;
    for (int frame = first; frame <= last; frame += step) {
        files.emplace_back(frame_reference(folder, frame), frame);
    }
    return files;
}

// One reference EXR against its scene and the record beside it (same stem, .json).
void check_reference(const std::filesystem::path& file, int frame, const Scene& scene) {
    SCOPED_TRACE(file.string());
    std::filesystem::path record_path = file;
    record_path.replace_extension(".json");
    ASSERT_TRUE(std::filesystem::is_regular_file(record_path));
    const nlohmann::json record = nlohmann::json::parse(read_file(record_path));
    const Image reference = read_image(file);
    EXPECT_EQ(reference.width, scene.camera.width);
    EXPECT_EQ(reference.height, scene.camera.height);
    EXPECT_EQ(record["file"], file.filename().string());
    EXPECT_EQ(record["resolution"][0], scene.camera.width);
    EXPECT_EQ(record["resolution"][1], scene.camera.height);
    EXPECT_EQ(record["frame"], frame);
    EXPECT_EQ(record["method"], "pt");
    EXPECT_EQ(record["nonfinite_samples"], 0);
    EXPECT_GE(record["spp"].get<int>(), 256);  // the walkthrough's 256 (CPU); the others >= 4096
    EXPECT_NE(record["command"].get<std::string>().find("--spp " +
                                                        std::to_string(record["spp"].get<int>())),
              std::string::npos);
    EXPECT_EQ(layer_names(reference),
              (std::vector<std::string>{"beauty", "direct", "indirect", "stddev"}));
}

TEST(Scenes, ReferencesMatchTheirScenes) {
    size_t scenes_with_references = 0;
    uintmax_t bytes = 0;
    for (const std::filesystem::path& folder : shipped_scenes()) {
        const bool still = std::filesystem::exists(folder / "reference.exr");
        const bool frames = std::filesystem::exists(folder / "reference");
        if (!still && !frames) {
            continue;
        }
        SCOPED_TRACE(folder.filename().string());
        ++scenes_with_references;
        const Scene scene = load_scene(folder / "scene.json");
        const bool animated = scene.animation.frame_end > scene.animation.frame_start;
        // One layout per scene: an animated scene's frames are not also a reference.exr.
        EXPECT_EQ(frames, animated);
        EXPECT_EQ(still, !animated);
        size_t files = 0;
        for (const auto& [file, frame] : reference_files(folder, scene)) {
            check_reference(file, frame, scene);
            bytes += std::filesystem::file_size(file);
            ++files;
        }
        if (frames) {
            // Nothing else in the folder: every frame's EXR and record.
            size_t entries = 0;
            for ([[maybe_unused]] const auto& entry :
                 std::filesystem::directory_iterator(folder / "reference")) {
                ++entries;
            }
            EXPECT_EQ(entries, 2 * files);
        }
    }
    // Every scene but the analytic furnace has one.
    EXPECT_EQ(scenes_with_references, shipped_scenes().size() - 1);
    // The repository's references stay under 40 MB (scenes/README.md).
    EXPECT_LT(bytes, uintmax_t{40} * 1000 * 1000) << bytes << " bytes of references";
}

}  // namespace
}  // namespace rc
