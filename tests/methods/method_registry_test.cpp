// The method registry (host/methods/registry.cpp) against what the methods do: every registered
// method renders through the frame loop, writes exactly the layers it declares (each written on
// its own when asked), reports its figures per frame in the stats file, is listed by --help,
// and an option of another method is refused by name.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "image/image.h"
#include "image/image_io.h"
#include "methods/registry.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::string cornell_box() {
    return (test::source_dir() / "scenes/cornell-box/scene.json").string();
}

// A small, quick render with `method`.
std::vector<std::string> quick_render(const MethodEntry& method,
                                      const std::filesystem::path& output) {
    std::vector<std::string> args = {"render",    cornell_box(), "-o", output.string(), "--method",
                                     method.name, "--spp",       "1",  "--width",       "12",
                                     "--height",  "10",          "-q"};
    const std::vector<std::string> quick = test::quick_method_options(method);
    args.insert(args.end(), quick.begin(), quick.end());
    return args;
}

// The layer a channel name belongs to: "R" is beauty, "direct.G" is direct.
std::string layer_of(const std::string& channel) {
    const size_t dot = channel.find('.');
    return dot == std::string::npos ? "beauty" : channel.substr(0, dot);
}

TEST(MethodRegistry, EveryMethodWritesExactlyTheLayersItDeclares) {
    const auto dir = test::scratch_dir("registry_layers");
    ASSERT_GE(method_registry().size(), 5u);
    for (const MethodEntry& method : method_registry()) {
        SCOPED_TRACE(method.name);
        const auto output = dir / (method.name + ".exr");
        std::vector<std::string> args = quick_render(method, output);
        args.insert(args.end(), {"--stats", (dir / (method.name + ".json")).string()});
        const test::CommandResult result = test::run_radcache(args);
        ASSERT_EQ(result.exit_code, 0) << result.output;
        const Image image = read_image(output);
        std::set<std::string> written;
        for (const std::string& channel : image.channel_names) {
            written.insert(layer_of(channel));
        }
        EXPECT_EQ(written, std::set<std::string>(method.aovs.begin(), method.aovs.end()));
        const nlohmann::json stats =
            nlohmann::json::parse(read_file(dir / (method.name + ".json")));
        EXPECT_EQ(stats["method"], method.name);
        ASSERT_EQ(stats["frames"].size(), 1u);
        EXPECT_EQ(stats["frames"][0]["output"], output.string());
        // Each declared layer can be written alone.
        for (const std::string& layer : method.aovs) {
            std::vector<std::string> one = quick_render(method, dir / "one.exr");
            one.insert(one.end(), {"--aovs", layer});
            const test::CommandResult alone = test::run_radcache(one);
            ASSERT_EQ(alone.exit_code, 0) << layer << ": " << alone.output;
            for (const std::string& channel : read_image(dir / "one.exr").channel_names) {
                EXPECT_EQ(layer_of(channel), layer);
            }
        }
    }
}

TEST(MethodRegistry, HelpListsEveryMethodAndOptionsOfOthersAreRefused) {
    const test::CommandResult help = test::run_radcache({"render", "--help"});
    ASSERT_EQ(help.exit_code, 0);
    for (const MethodEntry& method : method_registry()) {
        EXPECT_NE(help.output.find("      " + method.name + ": " + method.summary),
                  std::string::npos)
            << method.name;
        for (const OptionSpec& spec : method.options) {
            EXPECT_NE(help.output.find(spec.name), std::string::npos) << spec.name;
        }
    }
    // An option only other methods declare, given to each method, is refused by name.
    const auto dir = test::scratch_dir("registry_foreign");
    for (const MethodEntry& method : method_registry()) {
        for (const MethodEntry& other : method_registry()) {
            for (const OptionSpec& spec : other.options) {
                if (test::declares(method, spec.name) || !spec.value_name.empty()) {
                    continue;  // flags only: no value to invent
                }
                const test::CommandResult result =
                    test::run_radcache({"render", cornell_box(), "-o", (dir / "x.png").string(),
                                        "--method", method.name, spec.name});
                EXPECT_EQ(result.exit_code, 2) << method.name << " " << spec.name;
                EXPECT_NE(result.output.find(spec.name + " applies to --method"), std::string::npos)
                    << result.output;
                EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
            }
        }
    }
}

}  // namespace
}  // namespace rc
