#include "frame_renders.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "test_support.h"
#include "util/file_io.h"

namespace rc::test {

bool same_pixels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

std::filesystem::path frame_file(const std::filesystem::path& dir, const std::string& name,
                                 int frame) {
    char number[8];
    std::snprintf(number, sizeof number, "%04d", frame);
    return dir / (name + number + ".exr");
}

nlohmann::json render_frames(const std::filesystem::path& scene, const std::filesystem::path& dir,
                             const std::string& name, const std::vector<std::string>& args) {
    std::vector<std::string> command = {"render", scene.string()};
    command.insert(command.end(), args.begin(), args.end());
    command.insert(command.end(), {"-o", (dir / (name + "####.exr")).string(), "--stats",
                                   (dir / (name + ".json")).string(), "--quiet"});
    const CommandResult result = run_radcache(command);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return nlohmann::json::parse(read_file(dir / (name + ".json")));
}

void expect_static_glossy_records(const nlohmann::json& stats, int last) {
    const size_t records = stats["frames"][0]["temporal"]["radiance"]["records"].get<size_t>();
    EXPECT_GT(records, 0u);
    for (int f = 0; f <= last; ++f) {
        const nlohmann::json& r = stats["frames"][f]["temporal"]["radiance"];
        EXPECT_EQ(r["records"].get<size_t>(), records) << f;
        EXPECT_EQ(r["created"].get<size_t>(), f == 0 ? records : 0u) << f;
        EXPECT_EQ(r["reused"].get<size_t>(), f == 0 ? 0u : records) << f;
        EXPECT_EQ(r["recomputed"].get<size_t>(), 0u) << f;
        EXPECT_EQ(r["dropped"].get<size_t>(), 0u) << f;
        EXPECT_EQ(r["record_rays"].get<uint64_t>() > 0, f == 0) << f;
    }
}

}  // namespace rc::test
