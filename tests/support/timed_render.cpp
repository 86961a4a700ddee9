#include "timed_render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "image/image_io.h"
#include "methods/sample_passes.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc::test {

double relative_difference(const Image& a, const Image& b) {
    EXPECT_EQ(a.pixels.size(), b.pixels.size());
    double largest = 0.0, difference = 0.0;
    for (size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) {
        largest =
            std::max({largest, std::fabs(double(a.pixels[i])), std::fabs(double(b.pixels[i]))});
        difference = std::max(difference, std::fabs(double(a.pixels[i]) - double(b.pixels[i])));
    }
    return largest > 0.0 ? difference / largest : difference;
}

Image mean_of_passes(const std::vector<Image>& passes, const std::vector<int>& spp) {
    Image mean;
    int samples = 0;
    for (size_t i = 0; i < passes.size(); ++i) {
        add_weighted(&mean, samples, passes[i], spp[i]);
        samples += spp[i];
    }
    return mean;
}

void expect_passes_make_the_longer_render(const Image& longer, const std::vector<Image>& passes,
                                          const std::vector<int>& spp, double tolerance) {
    const Image mean = mean_of_passes(passes, spp);
    for (const std::string& layer : layer_names(longer)) {
        EXPECT_LT(relative_difference(select_layers(mean, {layer}), select_layers(longer, {layer})),
                  tolerance)
            << layer;
    }
    for (const Image& pass : passes) {
        EXPECT_GT(
            relative_difference(select_layers(pass, {"beauty"}), select_layers(longer, {"beauty"})),
            1e-3);
    }
}

void expect_finite_lit_beauty(const std::filesystem::path& path) {
    const Image image = select_layers(read_image(path), {"beauty"});
    double sum = 0.0;
    for (float v : image.pixels) {
        ASSERT_TRUE(std::isfinite(v)) << path;
        sum += v;
    }
    EXPECT_GT(sum, 0.0) << path;
}

nlohmann::json render_cornell_by_time(const std::string& scratch,
                                      const std::vector<std::string>& options, int max_spp) {
    const auto dir = scratch_dir(scratch);
    std::vector<std::string> words = {"render",
                                      (source_dir() / "scenes/cornell-box/scene.json").string(),
                                      "-o",
                                      (dir / "out.exr").string(),
                                      "--quiet",
                                      "--stats",
                                      (dir / "stats.json").string()};
    words.insert(words.end(), options.begin(), options.end());
    const CommandResult result = run_radcache(words);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    if (result.exit_code != 0) {
        return nlohmann::json::object();
    }
    expect_finite_lit_beauty(dir / "out.exr");
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
    const nlohmann::json& frame = stats["frames"][0];
    EXPECT_TRUE(frame.contains("time")) << frame.dump();
    if (!frame.contains("time")) {
        return nlohmann::json::object();
    }
    const nlohmann::json& time = frame["time"];
    EXPECT_GE(time["passes"].get<int>(), 1);
    EXPECT_GT(time["first_pass_seconds"].get<double>(), 0.0);
    EXPECT_EQ(time["spp"], frame["spp"]);
    EXPECT_EQ(stats["spp"], frame["spp"]);
    EXPECT_EQ(time["passes"].get<size_t>(), frame["passes"].size() + 1);
    int next = 1;
    for (const nlohmann::json& pass : frame["passes"]) {
        EXPECT_EQ(pass["first_sample"].get<int>(), next);
        EXPECT_LE(pass["spp"].get<int>(), max_spp);
        next += pass["spp"].get<int>();
    }
    EXPECT_EQ(next, frame["spp"].get<int>());
    return frame;
}

}  // namespace rc::test
