// The plan `--method auto` makes from its pilot's figures (methods/auto/auto_plan.h), on figures
// given here instead of measured: it never plans beyond the budget, more time never raises its
// predicted error, a budget the cheapest cache does not fit goes to the path tracer with the
// reason, fixed samples stay fixed; the materials' servers follow radiance caching's tables and
// the Phong exponent; the embedded model parses and a broken one is refused by key; a record ray's
// seconds follow the law through the throughput's two measurements.
#include "methods/auto/auto_plan.h"

#include <gtest/gtest.h>

#include <string>

#include "methods/auto/auto_materials.h"
#include "methods/auto/auto_model.h"
#include "methods/caching/glossy_spec.h"
#include "util/error.h"

namespace rc {
namespace {

struct Figures {
    AutoModel model = auto_model();
    DeviceThroughput throughput;
    PlanInputs in;

    Figures() {
        throughput.pt_seconds_per_ray = 1e-7;
        for (const char* method : {"ic", "rc", "sdrc"}) {
            throughput.cache_seconds_per_ray[method] = {{128, 1024}, {1e-7, 1e-7}};
            throughput.camera_seconds_per_ray[method] = 1e-7;
        }
        in.model = &model;
        in.throughput = &throughput;
        in.pixels = 256.0 * 256.0;
        in.noise.size = {32, 32};
        in.noise.v_pt = 0.2;
        in.noise.v_direct = 0.03;
        in.noise.indirect_fraction = 0.3;
        in.noise.rays_per_sample = 5.0;
        CachePilot cache;
        cache.size = {32, 32};
        cache.ic_rays = 128;
        cache.accuracy = 0.35;
        cache.cache_rays = 200000;
        cache.camera_rays_per_sample = 4.0;
        in.cache = cache;
        in.materials = {{"white", LobeServer::kDiffuse, 0.0, -1.0}};
        Material white;
        white.name = "white";
        in.cache_run = caching_run(in.materials, {white});
        in.pilot_seconds = 0.05;
    }
};

TEST(AutoPlan, NeverPlansBeyondTheBudget) {
    Figures f;
    for (double budget : {1.0, 3.0, 10.0, 30.0, 100.0, 1000.0}) {
        f.in.budget = budget;
        const AutoPlan plan = choose_plan(f.in);
        EXPECT_LE(plan.predicted_seconds + plan.pilot_seconds, budget * (1 + 1e-12)) << plan.line();
        EXPECT_GE(plan.spp, 1);
    }
}

TEST(AutoPlan, MoreTimeNeverRaisesTheTrustedError) {
    Figures f;
    double last = 1e300;
    for (double budget = 1.0; budget < 2000.0; budget *= 1.5) {
        f.in.budget = budget;
        const AutoPlan plan = choose_plan(f.in);
        EXPECT_LE(plan.trusted_relmse, last * (1 + 1e-12)) << plan.line();
        EXPECT_GE(plan.trusted_relmse, plan.predicted_relmse) << plan.line();
        last = plan.trusted_relmse;
    }
}

// Other knobs than the defaults win only when predicted better by more than the law's spread:
// with no spread the plan is the lowest predicted error of all the knobs; with a spread larger
// than any ratio of predictions, the defaults whenever they fit.
TEST(AutoPlan, TheDefaultKnobsAreKeptUnlessOthersWinBeyondTheSpread) {
    Figures f;
    f.in.budget = 60.0;
    f.model.error["ic"].spread = 1.0;
    const AutoPlan searched = choose_plan(f.in);
    ASSERT_TRUE(searched.caches()) << searched.line();
    f.model.error["ic"].spread = 1e6;
    const AutoPlan kept = choose_plan(f.in);
    ASSERT_TRUE(kept.caches()) << kept.line();
    EXPECT_TRUE(kept.default_knobs) << kept.line();
    EXPECT_EQ(kept.accuracy, declared_default("ic", "--accuracy"));
    EXPECT_EQ(kept.ic_rays, static_cast<int>(declared_default("ic", "--ic-rays")));
    EXPECT_LE(searched.predicted_relmse, kept.predicted_relmse * (1 + 1e-12));
    // No plan of the grid is predicted lower than the searched one.
    for (double spread : {1.0, 1.3, 2.0}) {
        f.model.error["ic"].spread = spread;
        const AutoPlan plan = choose_plan(f.in);
        EXPECT_TRUE(plan.default_knobs || plan.predicted_relmse * spread < kept.predicted_relmse)
            << plan.line();
    }
}

TEST(AutoPlan, ABudgetNoCacheFitsGoesToThePathTracerWithTheReason) {
    Figures f;
    f.in.cache->cache_rays = 1e10;  // every cache takes far longer than the budget
    f.in.budget = 10.0;
    const AutoPlan plan = choose_plan(f.in);
    EXPECT_EQ(plan.run.method, "pt");
    EXPECT_GT(plan.spp, 1);
    EXPECT_NE(plan.line().find("the cheapest cache needs about"), std::string::npos) << plan.line();
}

TEST(AutoPlan, FixedSamplesStayFixedAndWithoutTimeTheKnobsAreTheDefaults) {
    Figures f;
    f.in.spp = 7;
    f.in.spp_fixed = true;
    f.in.budget = 100.0;
    EXPECT_EQ(choose_plan(f.in).spp, 7);
    f.in.budget = 0.0;
    const AutoPlan plan = choose_plan(f.in);
    EXPECT_EQ(plan.spp, 7);
    EXPECT_EQ(plan.run.method, "ic");
    EXPECT_EQ(plan.accuracy, 0.35);
    EXPECT_EQ(plan.ic_rays, 1024);
}

TEST(AutoPlan, APilotBeyondItsShareOfTheBudgetIsAnError) {
    Figures f;
    f.in.pilot_seconds = 2.0;
    f.in.budget = 5.0;
    try {
        choose_plan(f.in);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.exit_code(), kExitUsage);
        EXPECT_NE(std::string(e.what()).find("--time 5: too short for --method auto"),
                  std::string::npos)
            << e.what();
    }
}

// A record ray's seconds follow s(R) = a + b / R through the two measurements: with s(128) = 8e-7
// and s(1024) = 4.5e-7, b = 3.5e-7 / (1/128 - 1/1024) = 5.12e-5 and a = 4e-7, so s(512) = 5e-7;
// more rays per record never cost more per ray, and measurements that say they do (noise) give
// one figure for every R.
TEST(AutoThroughput, ARecordRayCostsWhatTheTwoMeasurementsSayAndNoMoreWithMoreRays) {
    const CacheRayCost cost{{128, 1024}, {8e-7, 4.5e-7}};
    EXPECT_NEAR(cost.at(128), 8e-7, 1e-18);
    EXPECT_NEAR(cost.at(1024), 4.5e-7, 1e-18);
    EXPECT_NEAR(cost.at(512), 5e-7, 1e-18);
    EXPECT_NEAR(cost.at(1 << 16), 4e-7 + 5.12e-5 / 65536, 1e-18);
    for (int rays = 4; rays < (1 << 16); rays *= 2) {
        EXPECT_GE(cost.at(rays), cost.at(2 * rays)) << rays;
    }
    const CacheRayCost noisy{{128, 1024}, {4e-7, 4.4e-7}};
    EXPECT_NEAR(noisy.at(16), 4.4e-7, 1e-18);
    EXPECT_NEAR(noisy.at(4096), 4.4e-7, 1e-18);
}

TEST(AutoMaterials, RadianceCachingWhereItsTablesHoldTheLobeElseSdrcElsePathTracing) {
    const AutoModel& model = auto_model();
    Material diffuse;
    diffuse.name = "wall";
    Material broad;
    broad.name = "satin";
    broad.kind = MaterialKind::kPhong;
    broad.specular = glm::vec3(0.3f);
    broad.exponent = 16;
    Material sharp = broad;
    sharp.name = "copper";
    sharp.exponent = 200;
    Material mirror = broad;
    mirror.name = "mirror";
    mirror.exponent = 10000;
    const nlohmann::json tables =
        nlohmann::json::array({{{"name", "satin"}, {"order", 10}, {"fallback_fraction", 0.1}},
                               {{"name", "copper"}, {"order", 0}, {"fallback_fraction", 1.0}},
                               {{"name", "mirror"}, {"order", 0}, {"fallback_fraction", 1.0}}});
    const auto choices = choose_lobe_servers({diffuse, broad, sharp, mirror}, model, &tables);
    ASSERT_EQ(choices.size(), 4u);
    EXPECT_EQ(choices[0].server, LobeServer::kDiffuse);
    EXPECT_EQ(choices[1].server, LobeServer::kRadianceCache);
    EXPECT_EQ(choices[2].server, LobeServer::kSdrc);
    EXPECT_EQ(choices[3].server, LobeServer::kPath);
    // One glossy cache for every glossy lobe is that method; a mix is irradiance caching with the
    // per-material list.
    EXPECT_EQ(caching_run({choices[0], choices[1]}, {diffuse, broad}).method, "rc");
    EXPECT_EQ(caching_run({choices[0], choices[2]}, {diffuse, sharp}).method, "sdrc");
    const MethodRun mixed = caching_run(choices, {diffuse, broad, sharp, mirror});
    ASSERT_EQ(mixed.options.size(), 1u);
    EXPECT_EQ(mixed.options[0].first, "--glossy");
    // The list --glossy reads gives each material its server (path tracing for the rest).
    const std::vector<std::string> served = resolve_glossy_spec(
        parse_glossy_spec(mixed.options[0].second), {diffuse, broad, sharp, mirror});
    EXPECT_EQ(served, (std::vector<std::string>{"path", "rc", "sdrc", "path"}));
    EXPECT_EQ(model_key(choices), "sdrc");
}

TEST(AutoModel, TheEmbeddedModelParsesAndABrokenOneIsRefusedByKey) {
    const AutoModel& model = auto_model();
    for (const char* method : {"ic", "rc", "sdrc"}) {
        EXPECT_GT(model.cost_of(method).scale, 0.0) << method;
        EXPECT_NO_THROW(model.error_of(method));
    }
    EXPECT_FALSE(model.accuracies.empty());
    nlohmann::json broken = nlohmann::json::parse(R"({"pilot": {"divisor": 8}})");
    try {
        parse_auto_model(broken);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("'pilot.min_side'"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rc
