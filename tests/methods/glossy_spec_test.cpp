// The --glossy SPEC of `--method ic` (host/methods/caching/glossy_spec.h): what it reads and writes
// back, the plan's SPEC (glossy_spec_of) resolving to the plan again, and bad values refused on the
// command line with one error line naming the value, exit status 2, before rendering.
#include "methods/caching/glossy_spec.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

std::vector<Material> materials(const std::vector<std::string>& names) {
    std::vector<Material> all;
    for (const std::string& name : names) {
        all.push_back(Material{});
        all.back().name = name;
    }
    return all;
}

TEST(GlossySpec, ReadsCachesPerMaterialAndWritesThemBack) {
    const GlossySpec spec = parse_glossy_spec("copper=rc,satin=path,*=sdrc");
    ASSERT_EQ(spec.named.size(), 2u);
    EXPECT_EQ(spec.named[0].first, "copper");
    EXPECT_EQ(spec.named[0].second, "rc");
    EXPECT_EQ(spec.rest, "sdrc");
    EXPECT_EQ(spec.caches(), (std::vector<std::string>{"rc", "sdrc"}));
    EXPECT_EQ(glossy_spec_text(spec), "copper=rc,satin=path,*=sdrc");
    EXPECT_EQ(resolve_glossy_spec(spec, materials({"white", "satin", "copper"})),
              (std::vector<std::string>{"sdrc", "path", "rc"}));
    // A bare cache is the rest; path alone names no cache.
    EXPECT_EQ(glossy_spec_text(parse_glossy_spec("rc")), "rc");
    EXPECT_TRUE(parse_glossy_spec("rc").uniform());
    EXPECT_TRUE(parse_glossy_spec("path").caches().empty());
    EXPECT_EQ(parse_glossy_spec("copper=sdrc").rest, "path");
}

TEST(GlossySpec, BadValuesAreRefusedNamingThem) {
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"copper=foo", "unknown cache 'foo'"},
        {"foo", "unknown cache 'foo'"},
        {"copper=rc,copper=sdrc", "material 'copper' is listed twice"},
        {"*=rc,*=sdrc", "the rest (*) is given twice"},
        {"copper=", "got 'copper='"},
        {"rc,,sdrc", "got ''"},
        {"=rc", "got '=rc'"}};
    for (const auto& [value, message] : bad) {
        try {
            parse_glossy_spec(value);
            ADD_FAILURE() << value << " accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.exit_code(), kExitUsage) << value;
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
        }
    }
    try {
        resolve_glossy_spec(parse_glossy_spec("gold=rc"), materials({"white", "copper"}));
        ADD_FAILURE() << "gold accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.exit_code(), kExitUsage);
        EXPECT_NE(std::string(e.what()).find("no material 'gold'"), std::string::npos);
    }
}

// A plan per material written as SPEC and read back gives the plan.
TEST(GlossySpec, PlanSpecResolvesToThePlan) {
    const std::vector<Material> scene = materials({"white", "red", "copper", "satin", "brushed"});
    const std::vector<std::vector<GlossyServer>> plans = {
        {GlossyServer::kPath, GlossyServer::kPath, GlossyServer::kRc, GlossyServer::kSdrc,
         GlossyServer::kPath},
        {GlossyServer::kRc, GlossyServer::kRc, GlossyServer::kRc, GlossyServer::kRc,
         GlossyServer::kRc},
        {GlossyServer::kSdrc, GlossyServer::kSdrc, GlossyServer::kPath, GlossyServer::kRc,
         GlossyServer::kSdrc}};
    for (const std::vector<GlossyServer>& plan : plans) {
        const std::string text = glossy_spec_of(plan, scene);
        SCOPED_TRACE(text);
        const std::vector<std::string> resolved =
            resolve_glossy_spec(parse_glossy_spec(text), scene);
        for (size_t m = 0; m < plan.size(); ++m) {
            EXPECT_EQ(resolved[m], glossy_server_name(plan[m])) << m;
        }
    }
    EXPECT_EQ(glossy_spec_of(plans[1], scene), "rc");
    EXPECT_EQ(glossy_spec_of(plans[0], scene), "copper=rc,satin=sdrc,*=path");
    // Two materials of one name with different servers cannot be written.
    EXPECT_THROW(
        glossy_spec_of({GlossyServer::kRc, GlossyServer::kPath}, materials({"twin", "twin"})),
        Error);
}

// On the command line: one error line naming the value, exit status 2, no image.
TEST(GlossySpec, CommandLineRefusesBadValuesBeforeRendering) {
    const auto dir = test::scratch_dir("glossy_spec_cli");
    const std::string scene = (test::source_dir() / "scenes/glossy-box/scene.json").string();
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"gold=rc", "--glossy: the scene has no material 'gold'"},
        {"copper=foo", "--glossy: unknown cache 'foo'"},
        {"copper=rc,copper=sdrc", "--glossy: material 'copper' is listed twice"}};
    for (const auto& [value, message] : bad) {
        const auto out = dir / "out.exr";
        const test::CommandResult result =
            test::run_radcache({"render", scene, "--method", "ic", "--glossy", value, "--width",
                                "8", "--height", "8", "--spp", "1", "-o", out.string()});
        EXPECT_EQ(result.exit_code, 2) << value << ": " << result.output;
        EXPECT_NE(result.output.find(message), std::string::npos) << result.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << value;
    }
    // The option is ic's: other methods refuse it.
    const test::CommandResult pt = test::run_radcache(
        {"render", scene, "--method", "pt", "--glossy", "rc", "-o", (dir / "pt.exr").string()});
    EXPECT_EQ(pt.exit_code, 2) << pt.output;
    EXPECT_NE(pt.output.find("--glossy applies to --method ic only"), std::string::npos)
        << pt.output;
}

}  // namespace
}  // namespace rc
