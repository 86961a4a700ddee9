// `--method decomposition`: irradiance decomposition (DESIGN.md §6.6b; Arikan, Forsyth and
// O'Brien 2005) as a registered method: its options, the irradiance vector grid as its coarse
// solution, and its statistics per frame (docs/decomposition.md).
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <memory>
#include <regex>

#include "methods/decomposition/decomposition.h"
#include "methods/irradiance_vector_grid/ivg_options.h"
#include "methods/light_samples.h"
#include "methods/method.h"
#include "shared/decomposition.h"
#include "util/error.h"
#include "util/log.h"

namespace rc {
namespace {

constexpr int kDefaultClusterRays = 512;  // the paper's "512 rays per harmonic" (§4.1)
// §4.1's split test, hits inside the bounding sphere, looks inside 4 times it: with the paper's
// sphere the far field's relMSE on the Cornell box was 2.7 times higher (docs/decomposition.md).
constexpr double kDefaultSplitFactor = 4.0;
// Measured on the relief scene and the Cornell box (docs/decomposition.md): the near field
// within 1 % of the diagonal, clusters down to 5 % of it.
const char* const kDefaultAlpha = "1%";
const char* const kDefaultMinCluster = "5%";
// Points per split triangle of its radiosity: from the grid 4 (16 changed the relief's relMSE by
// 1 %); path-traced, 16 (4 raised it by 11 %; docs/decomposition.md).
constexpr int kRadiositySamplesGrid = 4;
constexpr int kRadiositySamplesPath = 16;
// Gathered radiosity (--decomp-radiosity gathered): direct light at 4 points per split triangle,
// DecompositionOptions' passes (docs/decomposition.md).
constexpr int kRadiositySamplesGathered = 4;
// --decomp-source radiosity: iterations of B(t) and the far field; with the tail extrapolated, 4
// gave the relief what 6 without it did (docs/decomposition.md, "The bounces' tail").
constexpr int kDefaultSourceIterations = 4;

// A length option (--alpha, --decomp-cluster): in scene units ("0.2", "0.2u") or a percentage of
// the diagonal of the scene's bounding box ("5%").
struct SceneLength {
    float value = 0.0f;
    bool relative = false;
};

SceneLength parse_length(const std::string& option, const std::string& text) {
    static const std::regex form(R"(^\s*([0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\s*(%|u)?\s*$)");
    std::smatch match;
    if (!std::regex_match(text, match, form)) {
        throw Error(option +
                        ": expected a length in scene units (\"0.2\", \"0.2u\") or a "
                        "percentage of the scene's diagonal (\"5%\"), got '" +
                        text + "'",
                    kExitUsage);
    }
    SceneLength length;
    length.value = std::stof(match[1].str());
    length.relative = match[2].str() == "%";
    if (!std::isfinite(length.value) || length.value < 0.0f) {
        throw Error(option + ": must be finite and at least 0, got '" + text + "'", kExitUsage);
    }
    return length;
}

// The length in scene units for the frame's world geometry.
float resolve_length(const SceneLength& length, const Scene& scene) {
    if (!length.relative) {
        return length.value;
    }
    glm::vec3 lower(std::numeric_limits<float>::max());
    glm::vec3 upper(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : scene.mesh.positions) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    const float diagonal = scene.mesh.positions.empty() ? 0.0f : glm::length(upper - lower);
    return 0.01f * length.value * diagonal;
}

nlohmann::json stats_json(const DecompositionStats& s, const DecompositionOptions& options,
                          uint64_t frame_rays, size_t pixels) {
    return {{"spp", options.spp},
            {"indirect_spp", std::max(options.spp, options.indirect_spp)},
            {"light_samples", options.light_samples},
            {"alpha", options.alpha},
            {"cluster_rays", options.cluster_rays},
            {"min_cluster_size", options.min_cluster_size},
            {"split_factor", options.split_factor},
            {"source", options.radiosity_source ? "radiosity" : options.source->source_name()},
            {"source_iterations", options.radiosity_source ? options.source_iterations : 0},
            {"source_change", s.source_change},
            {"source_tail_ratio", s.source_tail_ratio},
            {"source_rays_without_triangle", s.source_rays_without_triangle},
            {"radiosity", options.radiosity_passes > 0 ? "gathered" : "coarse"},
            {"radiosity_passes", s.radiosity_passes},
            {"uncovered_triangles", s.uncovered_triangles},
            {"records", s.sh_samples},
            {"sh_samples", s.sh_samples},
            {"clusters_sampled", s.clusters_sampled},
            {"clustered_points", s.clustered_points},
            {"triangles", {{"scene", s.scene_triangles}, {"near", s.near_triangles}}},
            {"near_triangles_per_point", {{"mean", s.near_mean}, {"max", s.near_max}}},
            {"far_samples_per_point", s.far_mean},
            {"far_uncovered_points", s.far_uncovered},
            {"served_samples", s.served_samples},
            {"radiosity_rays", s.radiosity_rays},
            {"cluster_rays_traced", s.cluster_rays},
            {"near_rays", s.near_rays},
            {"visibility", options.visibility_rays ? "rays" : "heuristic"},
            {"near_set", options.near_touching ? "touching" : "centroid"},
            {"gradients", options.gradients ? "on" : "off"},
            {"shading_rays", s.shading_rays},
            {"rays_per_pixel", static_cast<double>(frame_rays) / static_cast<double>(pixels)},
            {"seconds",
             {{"gbuffer", s.gbuffer_seconds},
              {"near_field", s.near_seconds},
              {"far_field", s.far_seconds},
              {"evaluation", s.evaluation_seconds},
              {"shading", s.shading_seconds}}}};
}

// Each device's share of pass 2 (several devices).
nlohmann::json devices_json(const std::vector<DecompDeviceShare>& shares) {
    nlohmann::json devices = nlohmann::json::array();
    for (const DecompDeviceShare& d : shares) {
        devices.push_back({{"device", d.device},
                           {"radiosity_triangles", d.radiosity_triangles},
                           {"radiosity_rays", d.radiosity_rays},
                           {"radiosity_seconds", d.radiosity_seconds},
                           {"cluster_ranges", d.cluster_ranges},
                           {"clusters", d.clusters},
                           {"cluster_rays", d.cluster_rays},
                           {"cluster_seconds", d.cluster_seconds},
                           {"chunks", d.chunks},
                           {"pixels", d.pixels},
                           {"shading_rays", d.shading_rays},
                           {"seconds", d.seconds}});
    }
    return devices;
}

class Decomposition final : public Method {
   public:
    Decomposition(const ParsedArguments& arguments, const MethodSettings& settings)
        : alpha_(parse_length("--alpha", arguments.value("--alpha", kDefaultAlpha))),
          min_cluster_(parse_length("--decomp-cluster",
                                    arguments.value("--decomp-cluster", kDefaultMinCluster))) {
        const std::string source = arguments.value("--decomp-source", "grid");
        if (source == "grid") {
            grid_options_ = ivg_options(arguments, settings);
        } else if (source == "path" || source == "radiosity") {
            refuse_ivg_options(arguments, "applies to --decomp-source grid only");
        } else {
            throw Error("--decomp-source: expected grid, path or radiosity, got '" + source + "'",
                        kExitUsage);
        }
        with_grid_ = source == "grid";
        options_.radiosity_source = source == "radiosity";
        if (arguments.has("--decomp-iterations") && !options_.radiosity_source) {
            throw Error("--decomp-iterations applies to --decomp-source radiosity only",
                        kExitUsage);
        }
        if (arguments.has("--decomp-extrapolate") && !options_.radiosity_source) {
            throw Error("--decomp-extrapolate applies to --decomp-source radiosity only",
                        kExitUsage);
        }
        options_.source_iterations =
            static_cast<int>(arguments.integer("--decomp-iterations", kDefaultSourceIterations));
        options_.source_extrapolate = arguments.value("--decomp-extrapolate", "on") == "on";
        // The gathered radiosity beats the grid's B(t) but not path-traced B(t) (the relief:
        // docs/decomposition.md), so each source has its own default; the radiosity source reads
        // the gathered one.
        const std::string radiosity = arguments.value(
            "--decomp-radiosity", with_grid_ || options_.radiosity_source ? "gathered" : "coarse");
        if (options_.radiosity_source && radiosity != "gathered") {
            throw Error("--decomp-radiosity " + radiosity +
                            ": --decomp-source radiosity reads the gathered radiosity",
                        kExitUsage);
        }
        if (radiosity != "gathered" && radiosity != "coarse") {
            throw Error("--decomp-radiosity: expected gathered or coarse, got '" + radiosity + "'",
                        kExitUsage);
        }
        if (radiosity == "gathered") {
            options_.radiosity_samples = kRadiositySamplesGathered;
            options_.traced_samples = static_cast<int>(
                arguments.integer("--decomp-traced-points", options_.traced_samples));
        } else if (arguments.has("--decomp-traced-points")) {
            throw Error("--decomp-traced-points: applies to --decomp-radiosity gathered only",
                        kExitUsage);
        } else {
            options_.radiosity_passes = 0;
            options_.radiosity_samples = with_grid_ ? kRadiositySamplesGrid : kRadiositySamplesPath;
        }
        settings.apply_to(options_);
        options_.cluster_rays =
            static_cast<int>(arguments.integer("--decomp-rays", kDefaultClusterRays));
        options_.split_factor =
            static_cast<float>(arguments.number("--decomp-split", kDefaultSplitFactor));
        options_.light_samples = light_samples(arguments);
        options_.indirect_spp = static_cast<int>(arguments.integer("--decomp-indirect-spp", 0));
        check_indirect_spp(options_);
        const std::string visibility = arguments.value("--decomp-visibility", "heuristic");
        if (visibility != "heuristic" && visibility != "rays") {
            throw Error("--decomp-visibility: expected heuristic or rays, got '" + visibility + "'",
                        kExitUsage);
        }
        options_.visibility_rays = visibility == "rays";
        // Counting the touching triangles whole helps the gathered radiosity on the relief, the
        // Cornell box and the two rooms but not the coarse one on the relief
        // (docs/decomposition.md, "The crease bias"), so the near set follows the radiosity.
        const std::string near =
            arguments.value("--decomp-near", radiosity == "gathered" ? "touching" : "centroid");
        if (near != "touching" && near != "centroid") {
            throw Error("--decomp-near: expected touching or centroid, got '" + near + "'",
                        kExitUsage);
        }
        options_.near_touching = near == "touching";
        const std::string gradients = arguments.value("--decomp-gradients", "on");
        if (gradients != "on" && gradients != "off") {
            throw Error("--decomp-gradients: expected on or off, got '" + gradients + "'",
                        kExitUsage);
        }
        options_.gradients = gradients == "on";
    }

    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        if (options_.radiosity_source && frame_devices(frame) > 1) {
            throw Error("--decomp-source radiosity renders on one device; --device names " +
                            std::to_string(frame_devices(frame)),
                        kExitUsage);
        }
        FrameResult result;
        std::unique_ptr<IrradianceVectorGrid> grid;
        PathContinuation path;
        if (with_grid_) {
            grid = build_frame_grid(frame, grid_options_, hooks, &result);
        }
        hooks.progress(0.5, "decomposition");
        DecompositionOptions options = options_;
        options.alpha = resolve_length(alpha_, frame.scene);
        options.min_cluster_size = resolve_length(min_cluster_, frame.scene);
        options.source = with_grid_ ? static_cast<const RadianceSource*>(grid.get()) : &path;
        IrradianceDecomposition decomposition(frame);
        DecompositionStats stats;
        result.image = decomposition.render(options, &stats);
        result.spp = options.spp;
        result.rays +=
            stats.radiosity_rays + stats.cluster_rays + stats.near_rays + stats.shading_rays;
        result.nonfinite_samples = stats.nonfinite_samples;
        result.first_nonfinite_pixel = stats.first_nonfinite_pixel;
        const size_t pixels = static_cast<size_t>(result.image.width) * result.image.height;
        result.stats.update(stats_json(stats, options, result.rays, pixels));
        if (!stats.devices.empty()) {
            result.stats["devices"] = devices_json(stats.devices);
        }
        log_note(std::to_string(stats.sh_samples) + " far-field samples, " +
                 std::to_string(stats.near_triangles) + " near-field triangles (alpha " +
                 std::to_string(options.alpha) + ")");
        return result;
    }

    // Several devices: the grid's photons, pass 2 (both terms and the render pass) and, with
    // path-traced continuation, the coarse radiosity and the cluster batches shared; the G-buffer,
    // the near field's split and the gathered radiosity on the first device.
    bool splits_across_devices() const override { return true; }

    std::vector<ProgramRequest> programs() const override {
        std::vector<ProgramRequest> programs = {
            {"decomposition/decomposition.cl",
             radiance_source_define(with_grid_ ? RC_RADIANCE_GRID : RC_RADIANCE_PATH)}};
        if (with_grid_) {
            programs.push_back({"irradiance_vector_grid/irradiance_vector_grid.cl", ""});
        }
        return programs;
    }

    DeviceMemoryNeed device_memory_need(const Scene& scene, const DeviceInfo&) const override {
        // IrradianceDecomposition::render: the G-buffer, both terms at every camera sample, the
        // film and its counters, held together in the render pass.
        const size_t pixels = image_pixels(options_.width, options_.height, scene);
        const size_t samples =
            pixels * static_cast<size_t>(std::max({options_.spp, options_.indirect_spp, 1}));
        DeviceMemoryNeed shading;
        shading.add("gbuffer", buffer_bytes(samples, sizeof(shared::GBufferSample)));
        shading.add("irradiance terms", buffer_bytes(samples, sizeof(shared::DecompIrradiance)));
        shading.add("film", buffer_bytes(pixels * RC_DECOMP_FILM_SLOTS, sizeof(shared::float4)));
        shading.add("counters", buffer_bytes(3, sizeof(unsigned)));
        shading.excludes = "the near field's triangles and the far field's records";
        if (!with_grid_) {
            return shading;
        }
        const IvgDeviceNeed grid = ivg_device_need(grid_options_, scene);
        shading.add_all(grid.built);
        return peak_of(grid.building, shading);
    }

   private:
    SceneLength alpha_;
    SceneLength min_cluster_;
    bool with_grid_ = true;
    IvgOptions grid_options_;
    DecompositionOptions options_;
};

std::vector<OptionSpec> decomposition_option_specs() {
    std::vector<OptionSpec> specs = {
        {"--alpha", "", "L",
         "decomposition: the near/far distance alpha, in scene units (\"0.2\", \"0.2u\") or a "
         "percentage of the scene's bounding-box diagonal (\"1%\"; default 1%)"},
        OptionSpec{"--decomp-rays", "", "N",
                   "decomposition: rays per cluster's far-field fit (default 512, the paper's)"}
            .integers(4, 1 << 16),
        {"--decomp-cluster", "", "L",
         "decomposition: a cluster of shading points less than L across is not split (a length "
         "as --alpha takes; the paper's rule: alpha; default 5%)"},
        OptionSpec{
            "--decomp-split", "", "S",
            "decomposition: a cluster is split while its rays hit inside S times its bounding "
            "sphere (>= 1; the paper's test is 1; default 4)"}
            .numbers(1.0, 1e3),
        OptionSpec{"--decomp-indirect-spp", "", "N",
                   "decomposition: camera samples per pixel where the far and near terms are "
                   "evaluated (>= --spp; default --spp): the first --spp are shaded fully, the "
                   "others add only the diffuse lobe's indirect light, for one camera ray each"}
            .integers(1, 4096),
        OptionSpec{"--decomp-traced-points", "", "N",
                   "decomposition, gathered radiosity: points per split triangle at which the "
                   "B(t) of those no far-field sample covers is path traced (default 16)"}
            .integers(1, 1024),
        OptionSpec{"--decomp-visibility", "", "NAME",
                   "decomposition: which near triangles count: heuristic (the paper's: all but "
                   "the back-facing and those below the horizon; default) or rays (of those, the "
                   "ones a shadow ray to the centroid reaches)"}
            .one_of({"heuristic", "rays"}),
        OptionSpec{"--decomp-near", "", "NAME",
                   "decomposition: the near set of eq. 4: touching (the split triangles with any "
                   "point within alpha; default with --decomp-radiosity gathered) or centroid "
                   "(those whose centroid lies within alpha, the paper's; default with "
                   "--decomp-radiosity coarse)"}
            .one_of({"touching", "centroid"}),
        OptionSpec{"--decomp-gradients", "", "on|off",
                   "decomposition: fit each far-field sample's translational gradient from its "
                   "rays' origins and interpolate with it (default on)"}
            .one_of({"on", "off"}),
        OptionSpec{"--decomp-radiosity", "", "NAME",
                   "decomposition: the near triangles' radiosity B(t): gathered (from the "
                   "decomposition's own far field and near field at the triangles; default with "
                   "--decomp-source grid) or coarse (read from the coarse solution, the paper's; "
                   "default with --decomp-source path)"}
            .one_of({"gathered", "coarse"}),
        OptionSpec{"--decomp-source", "", "NAME",
                   "decomposition: the coarse solution the rays read at their hits and the near "
                   "triangles' radiosity comes from: grid (the irradiance vector grid, default; "
                   "its options apply), path (path-traced continuation) or radiosity (the split "
                   "triangles' gathered radiosity B(t) at the rays' hits, iterated with the far "
                   "field; one device)"}
            .one_of({"grid", "path", "radiosity"}),
        OptionSpec{"--decomp-iterations", "", "K",
                   "decomposition, --decomp-source radiosity: iterations of the split triangles' "
                   "radiosity and the far field's fits, no ray each (default 4)"}
            .integers(1, 64),
        OptionSpec{"--decomp-extrapolate", "", "on|off",
                   "decomposition, --decomp-source radiosity: add the bounces the iterations "
                   "left out as a geometric tail, its ratio that of the last two changes (on, "
                   "default) or stop at the last iteration (off)"}
            .one_of({"on", "off"}),
        kLightSamplesOption,
    };
    for (OptionSpec& spec : ivg_option_specs()) {
        specs.push_back(std::move(spec));
    }
    return specs;
}

}  // namespace

MethodEntry decomposition_method_entry() {
    return {"decomposition",
            "irradiance decomposition: far-field SH samples per cluster, near field from nearby "
            "triangles' form factors",
            decomposition_option_specs(),
            {std::begin(kDecompositionAovs), std::end(kDecompositionAovs)},
            [](const ParsedArguments& arguments, const MethodSettings& settings) {
                return std::make_unique<Decomposition>(arguments, settings);
            }};
}

}  // namespace rc
