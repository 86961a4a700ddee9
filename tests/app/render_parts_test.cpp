// A render in parts (docs/farm.md): --crop windows hold the whole render's pixels, --sample-range
// parts with --write-sums add up to the whole render in `radcache merge`, and merge refuses parts
// of another render (another scene file, or a mesh it reads changed), naming the part and writing
// nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "image/image.h"
#include "image/image_io.h"
#include "scratch_files.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::string scene(const std::string& name) {
    return (test::source_dir() / "scenes" / name / "scene.json").string();
}

// `radcache render` of the Cornell box at 24x16 to `out` with `options`; must succeed.
Image render(const std::filesystem::path& out, std::vector<std::string> options,
             const std::string& scene_name = "cornell-box") {
    std::vector<std::string> args = {"render", scene(scene_name), "-o", out.string(), "--width",
                                     "24",     "--height",        "16", "--quiet"};
    args.insert(args.end(), options.begin(), options.end());
    const test::CommandResult result = test::run_radcache(args);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return read_image(out);
}

// `radcache merge out parts...`.
test::CommandResult merge(const std::filesystem::path& out,
                          const std::vector<std::filesystem::path>& parts) {
    std::vector<std::string> args = {"merge", "--quiet", out.string()};
    for (const auto& part : parts) {
        args.push_back(part.string());
    }
    return test::run_radcache(args);
}

// The channel `name` of `image`, pixel by pixel.
std::vector<float> channel(const Image& image, const std::string& name) {
    const auto found = std::find(image.channel_names.begin(), image.channel_names.end(), name);
    EXPECT_NE(found, image.channel_names.end()) << name;
    const auto c = static_cast<size_t>(found - image.channel_names.begin());
    std::vector<float> values;
    for (size_t p = 0; p < static_cast<size_t>(image.width) * image.height; ++p) {
        values.push_back(image.pixels[p * image.channels + c]);
    }
    return values;
}

// The pixels of columns x0.. and rows y0.. of `whole` that `window` covers.
Image window_of(const Image& whole, int x0, int y0, int width, int height) {
    Image cut(width, height, whole.channels);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < whole.channels; ++c) {
                cut.at(x, y, c) = whole.at(x0 + x, y0 + y, c);
            }
        }
    }
    return cut;
}

TEST(RenderParts, ACropHoldsTheWholeRendersPixelsBitwise) {
    const auto dir = test::scratch_dir("parts_crop");
    for (const char* method : {"pt", "ic"}) {
        const Image whole = render(dir / "whole.exr", {"--spp", "4", "--method", method});
        const Image crop =
            render(dir / "crop.exr", {"--spp", "4", "--method", method, "--crop", "5:17,3:11"});
        ASSERT_EQ(crop.width, 12);
        ASSERT_EQ(crop.height, 8);
        EXPECT_EQ(crop.origin_x, 5);
        EXPECT_EQ(crop.origin_y, 3);
        EXPECT_EQ(crop.full_width, 24);
        EXPECT_EQ(crop.metadata.at("radcache:crop"), "5:17,3:11");
        EXPECT_EQ(crop.pixels, window_of(whole, 5, 3, 12, 8).pixels) << method;
    }
}

TEST(RenderParts, CropsMergeIntoTheWholeRenderBitwise) {
    const auto dir = test::scratch_dir("parts_crops_merge");
    const Image whole = render(dir / "whole.exr", {"--spp", "4", "--write-sums"});
    render(dir / "left.exr", {"--spp", "4", "--write-sums", "--crop", "0:9,0:16"});
    render(dir / "right.exr", {"--spp", "4", "--write-sums", "--crop", "9:24,0:16"});
    const test::CommandResult result =
        merge(dir / "merged.exr", {dir / "right.exr", dir / "left.exr"});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Image merged = read_image(dir / "merged.exr");
    EXPECT_EQ(merged.width, 24);
    EXPECT_EQ(merged.channel_names, whole.channel_names);
    EXPECT_EQ(merged.pixels, whole.pixels);
}

TEST(RenderParts, MergeFramesMergesEachFrameOrWritesNone) {
    const auto dir = test::scratch_dir("parts_merge_frames");
    const std::vector<std::string> clip = {"--spp", "2", "--frames", "3:4"};
    auto with = [&](std::vector<std::string> more) {
        more.insert(more.end(), clip.begin(), clip.end());
        return more;
    };
    for (const auto& [name, crop] :
         {std::pair{"whole", "0:24,0:16"}, {"top", "0:24,0:5"}, {"bottom", "0:24,5:16"}}) {
        const test::CommandResult rendered =
            test::run_radcache(with({"render", scene("moving-sphere"), "-o",
                                     (dir / (std::string(name) + ".####.exr")).string(), "--width",
                                     "24", "--height", "16", "--quiet", "--crop", crop}));
        ASSERT_EQ(rendered.exit_code, 0) << rendered.output;
    }
    const auto merged = dir / "merged.####.exr";
    test::CommandResult result =
        test::run_radcache({"merge", "--quiet", "--frames", "3:4", merged.string(),
                            (dir / "top.####.exr").string(), (dir / "bottom.####.exr").string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    for (const char* frame : {"0003", "0004"}) {
        const Image whole = read_image(dir / (std::string("whole.") + frame + ".exr"));
        EXPECT_EQ(read_image(dir / (std::string("merged.") + frame + ".exr")).pixels, whole.pixels)
            << frame;
        EXPECT_EQ(whole.metadata.at("radcache:frame"), std::to_string(std::stoi(frame)));
    }
    EXPECT_NE(read_image(dir / "whole.0003.exr").pixels, read_image(dir / "whole.0004.exr").pixels);
    // Frame 5 has no parts: nothing is written, not even frames 3 and 4.
    result = test::run_radcache({"merge", "--quiet", "--frames", "3:5",
                                 (dir / "again.####.exr").string(), (dir / "top.####.exr").string(),
                                 (dir / "bottom.####.exr").string()});
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.output.find("top.0005.exr"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "again.0003.exr"));
    // A range of two billion frames: refused at the first frame without parts (frame 5), having
    // looked at no more than the frames before it, and leaving no probe file behind.
    const auto before = test::file_names(dir);
    result = test::run_radcache({"merge", "--quiet", "--frames", "3:2000000000",
                                 (dir / "again.####.exr").string(), (dir / "top.####.exr").string(),
                                 (dir / "bottom.####.exr").string()});
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.output.find("top.0005.exr: no such part (frame 5)"), std::string::npos)
        << result.output;
    EXPECT_EQ(test::file_names(dir), before);
}

TEST(RenderParts, SampleRangesAddUpToTheWholeRender) {
    const auto dir = test::scratch_dir("parts_ranges");
    const Image whole = render(dir / "whole.exr", {"--spp", "16", "--write-sums"});
    // One range of all the samples is the whole render, bitwise.
    const Image all = render(dir / "all.exr", {"--sample-range", "0:16", "--write-sums"});
    EXPECT_EQ(all.pixels, whole.pixels);
    std::vector<std::filesystem::path> parts;
    for (const char* range : {"0:3", "3:10", "10:16"}) {
        parts.push_back(dir / (std::string("part") + range[0] + range[1] + ".exr"));
        render(parts.back(), {"--sample-range", range, "--write-sums"});
    }
    const Image first = read_image(parts[0]);
    EXPECT_NE(first.pixels, window_of(whole, 0, 0, 24, 16).pixels) << "3 samples are not 16";
    const test::CommandResult result = merge(dir / "merged.exr", parts);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Image merged = read_image(dir / "merged.exr");
    EXPECT_EQ(merged.metadata.at("radcache:samples"), "0:16");
    EXPECT_EQ(channel(merged, "count.Y"), channel(whole, "count.Y"));
    for (const char* name : {"R", "G", "B", "stddev.R", "indirect.G", "beauty_sum.B"}) {
        const std::vector<float> a = channel(merged, name);
        const std::vector<float> b = channel(whole, name);
        // The float sums of 16 samples in another order: within a few float roundings.
        const double bound = std::string(name).rfind("stddev", 0) == 0 ? 1e-4 : 2e-6;
        for (size_t p = 0; p < a.size(); ++p) {
            ASSERT_LE(std::abs(a[p] - b[p]), bound * std::max(std::abs(b[p]), 1e-3f))
                << name << " pixel " << p;
        }
    }
}

struct Refused {
    std::vector<std::string> second_part;  // render options of the second part
    std::string scene = "cornell-box";
    std::string expected;
};

TEST(RenderParts, MergeRefusesPartsOfAnotherRenderWithoutOutput) {
    const auto dir = test::scratch_dir("parts_refused");
    render(dir / "a.exr", {"--sample-range", "0:4", "--write-sums"});
    const std::vector<Refused> cases = {
        {{"--sample-range", "4:8", "--write-sums"},
         "furnace",
         "another scene (its file or a file it reads)"},
        {{"--sample-range", "4:8", "--write-sums", "--seed", "3"},
         "cornell-box",
         "another options"},
        {{"--sample-range", "4:8", "--write-sums", "-D", "max_depth=2"},
         "cornell-box",
         "another options"},
        {{"--sample-range", "2:8", "--write-sums"}, "cornell-box", "overlap"},
        {{"--sample-range", "5:8", "--write-sums"}, "cornell-box", "4:5 are missing"},
        {{"--sample-range", "4:8"}, "cornell-box", "other layers"},
        {{"--sample-range", "4:8", "--write-sums", "--crop", "0:12,0:16"},
         "cornell-box",
         "overlaps"},
    };
    for (const Refused& refused : cases) {
        const auto b = dir / "b.exr";
        std::filesystem::remove(b);
        render(b, refused.second_part, refused.scene);
        const test::CommandResult result = merge(dir / "merged.exr", {dir / "a.exr", b});
        EXPECT_NE(result.exit_code, 0) << refused.expected;
        EXPECT_NE(result.output.find(refused.expected), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("b.exr"), std::string::npos) << result.output;
        EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "merged.exr")) << refused.expected;
    }
    render(dir / "plain.png", {"--spp", "2"});
    const test::CommandResult png = merge(dir / "merged.exr", {dir / "plain.png"});
    EXPECT_NE(png.exit_code, 0);
    EXPECT_NE(png.output.find("plain.png: not a part"), std::string::npos) << png.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "merged.exr"));
}

// A part is of another scene when a file the scene reads differs, though the scene file is the
// same: here one vertex of the tall block's mesh moved, or two meshes' files swapped their bytes.
// The same files under another directory are the same scene.
TEST(RenderParts, MergeRefusesPartsWhoseMeshDiffers) {
    const auto dir = test::scratch_dir("parts_mesh");
    const auto source = test::source_dir() / "scenes" / "cornell-box";
    for (const char* copy : {"a", "b", "c", "d"}) {
        std::filesystem::remove_all(dir / copy);
        std::filesystem::copy(source, dir / copy, std::filesystem::copy_options::recursive);
    }
    const auto mesh = dir / "b" / "meshes" / "tall_block.obj";
    std::string obj = read_file(mesh);
    const size_t vertex = obj.find("\nv ");
    ASSERT_NE(vertex, std::string::npos);
    obj.insert(vertex + 3, "1");  // the first vertex's x gains a leading digit
    std::ofstream(mesh, std::ios::binary) << obj;
    const auto part = [&](const char* copy, const char* range) {
        const auto out = dir / (std::string(copy) + ".exr");
        const test::CommandResult result = test::run_radcache(
            {"render", (dir / copy / "scene.json").string(), "-o", out.string(), "--width", "24",
             "--height", "16", "--quiet", "--sample-range", range, "--write-sums"});
        EXPECT_EQ(result.exit_code, 0) << result.output;
        return out;
    };
    // Copy d: the floor's and the light's meshes swapped, the same set of file contents.
    const auto floor = dir / "d" / "meshes" / "floor.obj";
    const auto light = dir / "d" / "meshes" / "light.obj";
    const std::string floor_bytes = read_file(floor);
    std::ofstream(floor, std::ios::binary) << read_file(light);
    std::ofstream(light, std::ios::binary) << floor_bytes;
    const auto a = part("a", "0:2");
    const auto b = part("b", "2:4");
    const auto c = part("c", "2:4");
    const auto d = part("d", "2:4");
    const test::CommandResult swapped = merge(dir / "merged.exr", {a, d});
    EXPECT_NE(swapped.exit_code, 0);
    EXPECT_NE(swapped.output.find("d.exr: another scene (its file or a file it reads)"),
              std::string::npos)
        << swapped.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "merged.exr"));
    const test::CommandResult refused = merge(dir / "merged.exr", {a, b});
    EXPECT_NE(refused.exit_code, 0);
    EXPECT_NE(refused.output.find("b.exr: another scene (its file or a file it reads)"),
              std::string::npos)
        << refused.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "merged.exr"));
    const test::CommandResult merged = merge(dir / "merged.exr", {a, c});
    EXPECT_EQ(merged.exit_code, 0) << merged.output;
}

// The merge places a part by its radcache:crop attribute only where the attribute is the EXR's
// data window: two crops whose attributes were swapped are refused, not merged upside down.
TEST(RenderParts, MergeRefusesACropAttributeThatIsNotItsDataWindow) {
    const auto dir = test::scratch_dir("parts_window");
    render(dir / "top.exr", {"--spp", "2", "--crop", "0:24,0:8"});
    render(dir / "bottom.exr", {"--spp", "2", "--crop", "0:24,8:16"});
    for (const auto& [name, crop] :
         {std::pair{"top.exr", "0:24,8:16"}, {"bottom.exr", "0:24,0:8"}}) {
        Image part = read_image(dir / name);
        part.metadata["radcache:crop"] = crop;
        write_image(dir / name, part, {});
    }
    const test::CommandResult result =
        merge(dir / "merged.exr", {dir / "top.exr", dir / "bottom.exr"});
    EXPECT_NE(result.exit_code, 0);
    EXPECT_NE(result.output.find("top.exr: its radcache:crop 0:24,8:16 is not its data window "
                                 "0:24,0:8"),
              std::string::npos)
        << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "merged.exr"));
}

// Crops of an irradiance-cache render read from one --cache-in path whose contents changed
// between them are parts of two renders.
TEST(RenderParts, MergeRefusesCropsOfAnotherCacheAtTheSamePath) {
    const auto dir = test::scratch_dir("parts_cache_in");
    const auto cache = dir / "records.bin";
    const auto crop = [&](const char* name, const char* window) {
        render(dir / name, {"--method", "ic", "--spp", "1", "--ic-rays", "16", "--crop", window,
                            "--cache-in", cache.string()});
        return dir / name;
    };
    render(dir / "seed1.exr", {"--method", "ic", "--spp", "1", "--ic-rays", "16", "--seed", "1",
                               "--cache-out", cache.string()});
    const auto top = crop("top.exr", "0:24,0:8");
    const auto same = crop("same.exr", "0:24,8:16");
    render(dir / "seed2.exr", {"--method", "ic", "--spp", "1", "--ic-rays", "16", "--seed", "2",
                               "--cache-out", cache.string()});
    const auto other = crop("other.exr", "0:24,8:16");
    const test::CommandResult refused = merge(dir / "merged.exr", {top, other});
    EXPECT_NE(refused.exit_code, 0);
    EXPECT_NE(refused.output.find("other.exr: another options"), std::string::npos)
        << refused.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "merged.exr"));
    const test::CommandResult merged = merge(dir / "merged.exr", {top, same});
    EXPECT_EQ(merged.exit_code, 0) << merged.output;
}

TEST(RenderParts, BadPartOptionsFailClearlyWithoutOutput) {
    const auto dir = test::scratch_dir("parts_bad");
    const std::string out = (dir / "out.exr").string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--crop", "1:2"}, "--crop: expected X0:X1,Y0:Y1, got '1:2'"},
        {{"--crop", "5:5,0:4"}, "--crop 5:5,0:4: an empty window"},
        {{"--crop", "0:25,0:4"}, "--crop 0:25,0:4 reaches outside the image (24x16)"},
        {{"--sample-range", "4"}, "--sample-range: expected S0:S1, got '4'"},
        {{"--sample-range", "8:4"}, "--sample-range 8:4: an empty range"},
        {{"--sample-range", "0:4", "--spp", "4"}, "drop --spp"},
        {{"--sample-range", "0:4", "-D", "time=2"},
         "renders S1 - S0 samples, but the render is by time (2 s"},
        {{"--sample-range", "0:4", "--method", "ic"}, "--sample-range applies to --method pt only"},
        {{"--write-sums", "--method", "ic"}, "--write-sums applies to --method pt only"},
        {{"--write-sums", "-o", (dir / "out.png").string()}, "--write-sums needs an .exr output"},
        {{"--write-sums", "--half"}, "drop --half"},
    };
    for (const auto& [options, expected] : cases) {
        std::vector<std::string> args = {"render", scene("cornell-box"), "--width",
                                         "24",     "--height",           "16"};
        args.insert(args.end(), options.begin(), options.end());
        if (std::find(options.begin(), options.end(), "-o") == options.end()) {
            args.insert(args.end(), {"-o", out});
        }
        const test::CommandResult result = test::run_radcache(args);
        EXPECT_EQ(result.exit_code, 2) << expected;
        EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
        EXPECT_TRUE(test::file_names(dir).empty()) << expected;
    }
    const test::CommandResult none = test::run_radcache({"merge", out});
    EXPECT_EQ(none.exit_code, 2);
    EXPECT_NE(none.output.find("at least one part"), std::string::npos) << none.output;
}

}  // namespace
}  // namespace rc
