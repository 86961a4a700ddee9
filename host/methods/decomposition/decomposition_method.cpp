// `--method decomposition`: irradiance decomposition (DESIGN.md §6.6b; Arikan, Forsyth and
// O'Brien 2005) as a registered method: its options, the irradiance vector grid as its coarse
// solution, and its statistics per frame (docs/decomposition.md).
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <memory>

#include "methods/decomposition/decomposition.h"
#include "methods/device_shares.h"
#include "methods/grid/ivg_options.h"
#include "methods/light_samples.h"
#include "methods/method.h"
#include "methods/sample_passes.h"
#include "scene/mesh_bounds.h"
#include "shared/decomposition.h"
#include "util/error.h"
#include "util/log.h"
#include "util/number_with_unit.h"
#include "util/timing.h"

namespace rc {
namespace {

// Points per split triangle of its radiosity: from the grid 4 (16 changed the relief's relMSE by
// 1 %); path-traced, 16 (4 raised it by 11 %; docs/decomposition.md).
constexpr int kRadiositySamplesGrid = 4;
constexpr int kRadiositySamplesPath = 16;
// Gathered radiosity (--decomp-radiosity gathered): direct light at 4 points per split triangle,
// DecompositionOptions' passes (docs/decomposition.md).
constexpr int kRadiositySamplesGathered = 4;

// A length option (--alpha, --decomp-cluster): in scene units ("0.2", "0.2u") or a percentage of
// the diagonal of the scene's bounding box ("5%").
struct SceneLength {
    float value = 0.0f;
    bool relative = false;
};

std::string length_text(const SceneLength& length) {
    return option_value_text(length.value) + (length.relative ? "%" : "u");
}

SceneLength parse_length(const std::string& option, const std::string& text) {
    const NumberWithUnit number = parse_number_with_unit(
        option, text, "%|u",
        "a length in scene units (\"0.2\", \"0.2u\") or a percentage of the scene's diagonal "
        "(\"5%\")");
    SceneLength length;
    length.value = number.value;
    length.relative = number.unit == "%";
    if (!std::isfinite(length.value) || length.value < 0.0f) {
        throw Error(option + ": must be finite and at least 0, got '" + text + "'", kExitUsage);
    }
    return length;
}

// The least scene extent (bounding box diagonal) the decomposition renders: the Cornell box
// (diagonal 960) scaled by 1e-11 (a diagonal of 9.6e-9) renders the unscaled picture (RMSE 1.6e-4
// with the same seed), by 1e-12 it is off by RMSE 2.5e-3 and by 1e-13 it drops non-finite samples
// (docs/lab/reliability.md, "Scene scale"). Below it the scene is refused, not rendered wrong.
constexpr float kMinDecompositionExtent = 0x1p-27f;

void check_decomposition_extent(const Scene& scene) {
    check_least_extent(scene.mesh, kMinDecompositionExtent, "--method decomposition: ", "",
                       "the least it renders, 2^-27", "scale the scene up or use another method");
}

// The length in scene units for the frame's world geometry.
float resolve_length(const SceneLength& length, const Scene& scene) {
    if (!length.relative) {
        return length.value;
    }
    return 0.01f * length.value * mesh_diagonal(scene.mesh);
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

// A later pass of a render by time (IrradianceDecomposition::render_samples): its own figures.
nlohmann::json pass_json(const DecompositionStats& s) {
    return {{"served_samples", s.served_samples},
            {"near_triangles_per_point", {{"mean", s.near_mean}, {"max", s.near_max}}},
            {"far_samples_per_point", s.far_mean},
            {"far_uncovered_points", s.far_uncovered},
            {"near_rays", s.near_rays},
            {"shading_rays", s.shading_rays},
            {"seconds",
             {{"gbuffer", s.gbuffer_seconds},
              {"evaluation", s.evaluation_seconds},
              {"shading", s.shading_seconds}}}};
}

// One device's share of pass 2 (several devices: add_device_shares).
nlohmann::json device_share_json(const DecompDeviceShare& d) {
    return {{"device", d.device},
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
            {"seconds", d.seconds}};
}

// The coarse solution the cluster rays read at their hits (--decomp-source).
enum class DecompSource { kGrid, kPath, kRadiosity };

// decomposition's options: the algorithm's, its lengths (resolved per frame against the scene's
// size), the coarse solution and the grid's.
struct DecompositionMethodOptions {
    DecompositionOptions decomposition;
    // Measured on the relief scene and the Cornell box (docs/decomposition.md): the near field
    // within 1 % of the diagonal, clusters down to 5 % of it.
    SceneLength alpha{1.0f, true};
    SceneLength min_cluster{5.0f, true};
    DecompSource source = DecompSource::kGrid;
    // --decomp-radiosity: gathered, or coarse (radiosity_passes 0); its default follows the
    // source, and the near set's the radiosity (finish_decomposition).
    bool gathered = true;
    IvgOptions grid;
};

OptionTable<DecompositionOptions> decomposition_table() {
    using O = DecompositionOptions;
    OptionTable<O> table;
    table
        .integer("--decomp-rays", "N", &O::cluster_rays, 4, 1 << 16,
                 "rays per cluster's far-field fit (the paper's: 512)")
        .knob(KnobDirection::kIncrease)
        .number("--decomp-split", "S", &O::split_factor, 1.0, 1e3,
                "a cluster is split while its rays hit inside S times its bounding sphere (the "
                "paper's test is 1)")
        .integer("--decomp-indirect-spp", "N", &O::indirect_spp, 1, 4096,
                 "camera samples per pixel where the far and near terms are evaluated (>= "
                 "--spp): the first --spp are shaded fully, the others add only the diffuse "
                 "lobe's indirect light, for one camera ray each")
        .default_note("--spp")
        .knob(KnobDirection::kIncrease)
        .integer("--decomp-traced-points", "N", &O::traced_samples, 1, 1024,
                 "gathered radiosity: points per split triangle at which the B(t) of those no "
                 "far-field sample covers is path traced")
        .knob(KnobDirection::kIncrease)
        .choice<bool>("--decomp-visibility", &O::visibility_rays,
                      {{"heuristic", false}, {"rays", true}},
                      "which near triangles count: heuristic (the paper's: all but the "
                      "back-facing and those below the horizon) or rays (of those, the ones a "
                      "shadow ray to the centroid reaches)")
        .choice<bool>("--decomp-near", &O::near_touching, {{"touching", true}, {"centroid", false}},
                      "the near set of eq. 4: touching (the split triangles with any point within "
                      "alpha) or centroid (those whose centroid lies within alpha, the paper's)")
        .default_note("touching with --decomp-radiosity gathered, centroid with coarse")
        .on_off("--decomp-gradients", &O::gradients,
                "fit each far-field sample's translational gradient from its rays' origins and "
                "interpolate with it")
        .integer("--decomp-iterations", "K", &O::source_iterations, 1, 64,
                 "--decomp-source radiosity: iterations of the split triangles' radiosity and the "
                 "far field's fits, no ray each")
        .knob(KnobDirection::kIncrease)
        .on_off("--decomp-extrapolate", &O::source_extrapolate,
                "--decomp-source radiosity: add the bounces the iterations left out as a "
                "geometric tail, its ratio that of the last two changes (on) or stop at the last "
                "iteration (off)");
    add_light_samples_option(table, &O::light_samples);
    return table;
}

OptionTable<DecompositionMethodOptions> decomposition_method_table() {
    using O = DecompositionMethodOptions;
    OptionTable<O> table;
    table
        .parsed<SceneLength>(
            "--alpha", "L", &O::alpha, "length",
            [](const std::string& text) { return parse_length("--alpha", text); }, length_text,
            "the near/far distance alpha, in scene units (\"0.2\", \"0.2u\") or a percentage of "
            "the scene's bounding-box diagonal (\"1%\")")
        .parsed<SceneLength>(
            "--decomp-cluster", "L", &O::min_cluster, "length",
            [](const std::string& text) { return parse_length("--decomp-cluster", text); },
            length_text,
            "a cluster of shading points less than L across is not split (a length as --alpha "
            "takes; the paper's rule: alpha)")
        .knob(KnobDirection::kDecrease)
        .choice<DecompSource>("--decomp-source", &O::source,
                              {{"grid", DecompSource::kGrid},
                               {"path", DecompSource::kPath},
                               {"radiosity", DecompSource::kRadiosity}},
                              "the coarse solution the rays read at their hits and the near "
                              "triangles' radiosity comes from: grid (the irradiance vector grid; "
                              "its options apply), path (path-traced continuation) or radiosity "
                              "(the split triangles' gathered radiosity B(t) at the rays' hits, "
                              "iterated with the far field; one device)")
        .choice<bool>("--decomp-radiosity", &O::gathered, {{"gathered", true}, {"coarse", false}},
                      "the near triangles' radiosity B(t): gathered (from the decomposition's own "
                      "far field and near field at the triangles) or coarse (read from the coarse "
                      "solution, the paper's)")
        .default_note("gathered with --decomp-source grid or radiosity, coarse with path")
        .include(decomposition_table(), &O::decomposition)
        .include(ivg_option_table(), &O::grid);
    return table;
}

// The rules between decomposition's options: the defaults that follow the source and the
// radiosity, and the options that apply to one source or one radiosity only.
void finish_decomposition(DecompositionMethodOptions& options, const ParsedArguments& arguments) {
    DecompositionOptions& d = options.decomposition;
    const bool radiosity_source = options.source == DecompSource::kRadiosity;
    if (options.source == DecompSource::kGrid) {
        finish_ivg_options(options.grid, arguments);
    } else {
        refuse_ivg_options(arguments, "applies to --decomp-source grid only");
    }
    for (const char* option : {"--decomp-iterations", "--decomp-extrapolate"}) {
        if (arguments.has(option) && !radiosity_source) {
            throw Error(std::string(option) + " applies to --decomp-source radiosity only",
                        kExitUsage);
        }
    }
    // The gathered radiosity beats the grid's B(t) but not path-traced B(t) (the relief:
    // docs/decomposition.md), so each source has its own default; the radiosity source reads
    // the gathered one.
    if (!arguments.has("--decomp-radiosity")) {
        options.gathered = options.source != DecompSource::kPath;
    }
    if (radiosity_source && !options.gathered) {
        throw Error(
            "--decomp-radiosity coarse: --decomp-source radiosity reads the gathered radiosity",
            kExitUsage);
    }
    if (!options.gathered && arguments.has("--decomp-traced-points")) {
        throw Error("--decomp-traced-points: applies to --decomp-radiosity gathered only",
                    kExitUsage);
    }
    // Counting the touching triangles whole helps the gathered radiosity on the relief, the
    // Cornell box and the two rooms but not the coarse one on the relief
    // (docs/lab/decomposition.md, "The crease bias"), so the near set follows the radiosity.
    if (!arguments.has("--decomp-near")) {
        d.near_touching = options.gathered;
    }
    d.radiosity_source = radiosity_source;
    if (options.gathered) {
        d.radiosity_samples = kRadiositySamplesGathered;
    } else {
        d.radiosity_passes = 0;
        d.radiosity_samples =
            options.source == DecompSource::kGrid ? kRadiositySamplesGrid : kRadiositySamplesPath;
    }
}

// The algorithm's options with the shared settings applied; Error (exit status 2) for
// --decomp-indirect-spp below --spp, and for --decomp-indirect-spp with --time (a render by time
// adds fully shaded camera samples in passes; the diffuse-only ones have no place in them).
DecompositionOptions decomposition_options(const DecompositionMethodOptions& options,
                                           const MethodSettings& settings) {
    DecompositionOptions d = options.decomposition;
    settings.apply_to(d);
    check_indirect_spp(d);
    if (settings.time > 0.0 && d.indirect_spp != 0) {
        throw Error(
            "--decomp-indirect-spp: not with --time (a render by time adds fully shaded camera "
            "samples while the time lasts; give --spp, the most samples a pass takes, alone)",
            kExitUsage);
    }
    return d;
}

class Decomposition final : public Method {
   public:
    Decomposition(const DecompositionMethodOptions& options, const MethodSettings& settings)
        : settings_time_(settings.time),
          alpha_(options.alpha),
          min_cluster_(options.min_cluster),
          with_grid_(options.source == DecompSource::kGrid),
          options_(decomposition_options(options, settings)) {
        if (with_grid_) {
            grid_options_ = ivg_options(options.grid, settings);
        }
    }

    // Without --time: the coarse solution, the decomposition and --spp camera samples. With
    // --time: the first pass (methods/sample_passes.h) builds the coarse solution and the near
    // and far fields from one camera sample per pixel (the far field's clusters are those of the
    // first sample of each pixel either way) and shades it; each later pass shades its camera
    // samples over the same fields, at most --spp a pass.
    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        if (options_.radiosity_source && frame_devices(frame) > 1) {
            throw Error("--decomp-source radiosity renders on one device; --device names " +
                            std::to_string(frame_devices(frame)),
                        kExitUsage);
        }
        std::unique_ptr<IrradianceVectorGrid> grid;
        PathContinuation path;
        IrradianceDecomposition decomposition(frame);
        DecompositionOptions options = options_;
        if (!(settings_time_ > 0.0)) {
            return build_and_render(frame, hooks, &grid, &path, &decomposition, &options);
        }
        FrameResult result = render_sample_passes(
            {settings_time_, options_.spp, {}}, hooks, [&](const SamplePass& pass) {
                if (pass.first == 0) {
                    options.spp = pass.spp;
                    const auto start = SteadyClock::now();
                    FrameResult first =
                        build_and_render(frame, hooks, &grid, &path, &decomposition, &options);
                    // The cache: all but the camera samples' G-buffer, terms and shading.
                    const nlohmann::json& phases = first.stats["seconds"];
                    first.cache_seconds = seconds_since(start) - phases.value("gbuffer", 0.0) -
                                          phases.value("evaluation", 0.0) -
                                          phases.value("shading", 0.0);
                    return first;
                }
                DecompositionStats stats;
                FrameResult part;
                part.image = decomposition.render_samples(pass.first, pass.spp, &stats);
                part.spp = pass.spp;
                part.rays = stats.near_rays + stats.shading_rays;
                part.nonfinite_samples = stats.nonfinite_samples;
                part.first_nonfinite_pixel = stats.first_nonfinite_pixel;
                part.stats = pass_json(stats);
                add_device_shares(stats.devices, &part.stats, device_share_json);
                return part;
            });
        const size_t pixels = static_cast<size_t>(result.image.width) * result.image.height;
        result.stats["spp"] = result.spp;
        result.stats["indirect_spp"] = result.spp;
        result.stats["rays_per_pixel"] =
            static_cast<double>(result.rays) / static_cast<double>(std::max<size_t>(pixels, 1));
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
        // The grid is built first and read until the frame ends.
        return with_grid_ ? with_grid_need(grid_options_, scene, shading) : shading;
    }

   private:
    // The coarse solution (*grid or *path), the decomposition's fields and its render of
    // options->spp camera samples (the first of a render by time).
    FrameResult build_and_render(const FrameScene& frame, const FrameHooks& hooks,
                                 std::unique_ptr<IrradianceVectorGrid>* grid,
                                 PathContinuation* path, IrradianceDecomposition* decomposition,
                                 DecompositionOptions* options) {
        check_decomposition_extent(frame.scene);
        FrameResult result;
        if (with_grid_) {
            *grid = build_frame_grid(frame, grid_options_, hooks, &result);
        }
        hooks.progress(0.5, "decomposition");
        options->alpha = resolve_length(alpha_, frame.scene);
        options->min_cluster_size = resolve_length(min_cluster_, frame.scene);
        options->source = with_grid_ ? static_cast<const RadianceSource*>(grid->get()) : path;
        DecompositionStats stats;
        result.image = decomposition->render(*options, &stats);
        result.spp = options->spp;
        result.rays +=
            stats.radiosity_rays + stats.cluster_rays + stats.near_rays + stats.shading_rays;
        result.nonfinite_samples = stats.nonfinite_samples;
        result.first_nonfinite_pixel = stats.first_nonfinite_pixel;
        const size_t pixels = static_cast<size_t>(result.image.width) * result.image.height;
        result.stats.update(stats_json(stats, *options, result.rays, pixels));
        add_device_shares(stats.devices, &result.stats, device_share_json);
        log_note(std::to_string(stats.sh_samples) + " far-field samples, " +
                 std::to_string(stats.near_triangles) + " near-field triangles (alpha " +
                 std::to_string(options->alpha) + ")");
        return result;
    }

    double settings_time_ = 0.0;  // --time (0: none)
    SceneLength alpha_;
    SceneLength min_cluster_;
    bool with_grid_ = true;
    DecompositionOptions options_;
    IvgOptions grid_options_;
};

}  // namespace

MethodEntry decomposition_method_entry() {
    return method_entry<DecompositionMethodOptions>(
        {.name = "decomposition",
         .summary = "irradiance decomposition: far-field SH samples per cluster, near field from "
                    "nearby triangles' form factors",
         .aovs = {std::begin(kDecompositionAovs), std::end(kDecompositionAovs)},
         .table = decomposition_method_table(),
         .finish = finish_decomposition,
         .check =
             [](const DecompositionMethodOptions& options, const MethodSettings& settings) {
                 decomposition_options(options, settings);
                 if (options.source == DecompSource::kGrid) {
                     ivg_options(options.grid, settings);
                 }
             },
         .create =
             [](const DecompositionMethodOptions& options, const MethodSettings& settings) {
                 return std::make_unique<Decomposition>(options, settings);
             }});
}

}  // namespace rc
