#include "methods/decomposition/decomposition.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <glm/geometric.hpp>
#include <limits>
#include <string>

#include "image/film.h"
#include "methods/caching/record_store.h"
#include "methods/decomposition/clusters.h"
#include "methods/decomposition/decomp_cluster_split.h"
#include "methods/decomposition/decomp_device_split.h"
#include "methods/decomposition/decomp_radiosity_split.h"
#include "methods/decomposition/near_grid.h"
#include "methods/decomposition/triangle_split.h"
#include "methods/scene_arguments.h"
#include "methods/shared_settings.h"
#include "scene/camera.h"
#include "util/error.h"
#include "util/glm_helpers.h"
#include "util/timing.h"

namespace rc {

const char* const kDecompositionAovs[7] = {"beauty", "direct",    "indirect",  "albedo",
                                           "normal", "far-field", "near-field"};

namespace {

constexpr size_t kMaxBatchRays = size_t{1} << 22;  // cluster rays per launch
constexpr size_t kMaxNearTriangles = size_t{1} << 22;
// The fit's Tikhonov weight per kept ray relative to 1 / (4 pi) (rc_decomp_solve): it shrinks a
// fit of a constant over a hemisphere by 0.01 % and keeps a cluster whose kept rays cover a
// quarter of the sphere within a few per cent of its irradiance, where no weight lets the
// unsampled directions swing (docs/decomposition.md).
constexpr float kRidge = 1e-3f;
// The Tikhonov weight of the gradient part of the first-order fit (--decomp-gradients on), per
// kept ray relative to 1 / (4 pi), the offsets in units of their RMS distance from the centre
// (rc_decomp_fit_with_gradients): an axis along which the cluster's origins spread with mean
// square v of that unit keeps v / (v + 0.01) of its derivative, so a flat cluster's normal gets
// none and an axis spread less than a tenth of the RMS distance keeps at most half
// (docs/decomposition.md).
constexpr float kGradientRidge = 1e-2f;
// A far-field sample is interpolated within kReach times its cluster's bounding radius, that
// radius taken as at least kMinRadiusFootprints pixel footprints (a cluster of one point).
// Measured on the Cornell box (docs/decomposition.md): 1.5 beats 2 and 1.2.
constexpr float kReach = 1.5f;
constexpr float kMinRadiusFootprints = 2.0f;

// Error (exit status 2) for options render() cannot honour; `samples` camera samples in all.
void check_options(const DecompositionOptions& options, size_t samples) {
    if (options.source == nullptr) {
        throw Error("irradiance decomposition: no coarse solution (radiance source) given");
    }
    if (options.spp < 1) {
        throw Error("irradiance decomposition needs at least one camera sample per pixel",
                    kExitUsage);
    }
    check_indirect_spp(options);
    if (!(options.alpha >= 0.0f) || !std::isfinite(options.alpha)) {
        throw Error("--alpha must be a finite length >= 0", kExitUsage);
    }
    if (options.cluster_rays < 1 || options.min_cluster < 1 || options.light_samples < 1 ||
        options.radiosity_samples < 1 || options.radiosity_passes < 0 ||
        options.traced_samples < 1) {
        throw Error("--decomp-rays and --light-samples must be at least 1", kExitUsage);
    }
    if (!(options.split_factor >= 1.0f) || !std::isfinite(options.split_factor)) {
        throw Error("--decomp-split must be a finite factor >= 1", kExitUsage);
    }
    if (!(options.min_cluster_size >= 0.0f) || !std::isfinite(options.min_cluster_size)) {
        throw Error("--decomp-cluster must be a finite length >= 0", kExitUsage);
    }
    if (options.radiosity_source && !(options.alpha > 0.0f)) {
        throw Error(
            "--alpha 0: --decomp-source radiosity reads the split triangles' radiosity "
            "(needs --alpha > 0)",
            kExitUsage);
    }
    if (options.radiosity_source && options.radiosity_passes < 1) {
        throw Error("--decomp-source radiosity reads the gathered radiosity", kExitUsage);
    }
    if (options.radiosity_source && options.source_iterations < 1) {
        throw Error("--decomp-iterations must be at least 1", kExitUsage);
    }
    if (samples > std::numeric_limits<uint32_t>::max()) {
        throw Error("irradiance decomposition: width x height x spp exceeds 2^32 camera samples",
                    kExitUsage);
    }
}

// The image of the render pass's film sums.
Image decomposition_image(const std::vector<shared::float4>& sums, int width, int height) {
    return unpack_film(sums, RC_DECOMP_FILM_SLOTS, width, height,
                       {{"beauty", RC_DECOMP_FILM_BEAUTY},
                        {"direct", RC_DECOMP_FILM_DIRECT},
                        {"indirect", RC_DECOMP_FILM_INDIRECT},
                        {"albedo", RC_DECOMP_FILM_ALBEDO},
                        {"normal", RC_DECOMP_FILM_NORMAL},
                        {"far-field", RC_DECOMP_FILM_FAR},
                        {"near-field", RC_DECOMP_FILM_NEAR}});
}

// Records (the shared layout the record grid reads) of spheres of radius `reach[i]` about
// `centres[i]`.
std::vector<shared::Record> reach_records(const std::vector<glm::vec3>& centres,
                                          const std::vector<float>& reach,
                                          const std::vector<glm::vec3>& normals) {
    std::vector<shared::Record> records;
    records.reserve(centres.size());
    for (size_t i = 0; i < centres.size(); ++i) {
        shared::Record record = make_record(centres[i], normals[i]);
        record.radius = reach[i];
        records.push_back(record);
    }
    return records;
}

}  // namespace

void check_indirect_spp(const DecompositionOptions& options) {
    if (options.indirect_spp != 0 && options.indirect_spp < options.spp) {
        throw Error("--decomp-indirect-spp " + std::to_string(options.indirect_spp) +
                        ": must be at least --spp (" + std::to_string(options.spp) + ")",
                    kExitUsage);
    }
}

// A cluster waiting for its rays: its points and its random stream (clusters are numbered as
// they are made, so the streams do not depend on the batches).
struct IrradianceDecomposition::PendingCluster {
    PointCluster cluster;
    uint32_t stream = 0;
};

IrradianceDecomposition::IrradianceDecomposition(const FrameScene& frame)
    : FrameBound(frame), frame_(frame) {}

IrradianceDecomposition::~IrradianceDecomposition() = default;

Kernel& IrradianceDecomposition::kernel(const char* name) {
    auto found = kernels_.find(name);
    if (found == kernels_.end()) {
        Kernel k =
            context_.kernel("decomposition/decomposition.cl", name, source_->build_options());
        found = kernels_.emplace(name, std::move(k)).first;
    }
    return found->second;
}

void IrradianceDecomposition::compute_gbuffer() {
    const size_t count = static_cast<size_t>(params_.width) * params_.height *
                         static_cast<size_t>(params_.camera_spp);
    gbuffer_ = Buffer<shared::GBufferSample>(context_, count, "decomp_gbuffer");
    context_.launch(kernel("decomp_gbuffer"), count, params_, camera_,
                    SceneArguments(bvh_, device_scene_), gbuffer_);
    samples_ = gbuffer_.download();
}

// §5 and §6 pass 1: the scene's triangles split to alpha and the grid that finds a point's near
// set (near_grid.h; their radiosity: coarse_radiosity or gather_radiosity).
void IrradianceDecomposition::build_near_field(const DecompositionOptions& options) {
    triangles_.clear();
    uncovered_.clear();
    TriangleSplit split;
    if (options.alpha > 0.0f) {
        split = split_triangle_tree(scene_.mesh, options.alpha, kMaxNearTriangles);
    }
    triangles_ = std::move(split.triangles);
    if (radiosity_source_) {
        split_nodes_ = Buffer<shared::SplitNode>(context_, split.nodes, "decomp_split_nodes");
        split_roots_ = Buffer<uint32_t>(context_, split.roots, "decomp_split_roots");
    }
    stats_.scene_triangles = scene_.mesh.triangles.size();
    stats_.near_triangles = triangles_.size();
    triangle_buffer_ = Buffer<shared::NearTriangle>(context_, triangles_, "decomp_triangles");
    radiance_buffer_ = Buffer<shared::float4>(context_, triangles_.size(), "decomp_radiance");
    radiance_buffer_.fill_zero();
    near_grid_ = build_near_grid(triangles_, options.alpha, params_.near_set);
    near_start_ = Buffer<int>(context_, near_grid_.cell_start, "decomp_near_start");
    near_list_ = Buffer<int>(context_, near_grid_.cell_records, "decomp_near_list");
}

// §6 pass 1, "the average radiosity value over all visible triangles", from the coarse solution:
// B(t) / pi of the triangles `listed` into `radiance` (its other entries untouched).
void IrradianceDecomposition::coarse_radiosity(const std::vector<uint32_t>& listed,
                                               Buffer<shared::float4>& radiance) {
    if (listed.empty()) {
        return;
    }
    if (frame_devices(frame_) > 1 && dynamic_cast<const PathContinuation*>(source_) != nullptr) {
        stats_.radiosity_rays +=
            split_coarse_radiosity(frame_, params_, source_->build_options(), triangles_,
                                   triangle_buffer_, listed, radiance, &radiosity_shares_);
        return;
    }
    const Buffer<uint32_t> list(context_, listed, "decomp_radiosity_list");
    Buffer<unsigned> counters(context_, 1, "decomp_radiosity_counters");
    counters.fill_zero();
    context_.launch(kernel("decomp_radiosity"), listed.size(), params_,
                    SceneArguments(bvh_, device_scene_), *source_, triangle_buffer_, list, radiance,
                    counters);
    stats_.radiosity_rays += counters.download()[0];
}

// The same radiosity gathered from the decomposition's own terms at the triangles (after the far
// field): once what each sends besides its diffuse indirect light (rays), and which ones a
// far-field sample covers; B(t) path traced for the others; then `passes` passes with
// no ray (but --decomp-visibility's): the first with I_N = 0, pass k reading pass k - 1's B(t) in
// eq. 4.
void IrradianceDecomposition::gather_radiosity(int passes, int traced_samples) {
    stats_.radiosity_passes = passes;
    if (triangles_.empty()) {
        return;
    }
    GatherInputs inputs;
    prepare_gather(traced_samples, &inputs);
    Buffer<shared::float4> previous(context_, triangles_.size(), "decomp_radiance_previous");
    for (int pass = 0; pass < passes; ++pass) {
        std::swap(previous, radiance_buffer_);
        gather_pass(inputs, previous, pass > 0);
    }
    stats_.radiosity_rays += inputs.counters.download()[0];
}

void IrradianceDecomposition::prepare_gather(int traced_samples, GatherInputs* in) {
    const size_t count = triangles_.size();
    in->direct = Buffer<shared::float4>(context_, count, "decomp_radiosity_direct");
    in->reflectance = Buffer<shared::float4>(context_, count, "decomp_reflectance");
    in->traced = Buffer<shared::float4>(context_, count, "decomp_radiance_traced");
    in->covered = Buffer<uint32_t>(context_, count, "decomp_covered");
    in->counters = Buffer<unsigned>(context_, 1, "decomp_radiosity_counters");
    in->counters.fill_zero();
    in->traced.fill_zero();
    context_.launch(kernel("decomp_radiosity_direct"), count, params_,
                    SceneArguments(bvh_, device_scene_), triangle_buffer_, in->direct,
                    in->reflectance, in->counters);
    context_.launch(kernel("decomp_radiosity_coverage"), count, far_grid_.grid, far_start_,
                    far_list_, far_records_, far_coefficients_, triangle_buffer_,
                    reach_needed_ ? 1u : 0u, in->covered);
    const std::vector<uint32_t> flags = in->covered.download();
    for (size_t t = 0; t < count; ++t) {
        if (flags[t] == 0) {
            uncovered_.push_back(static_cast<uint32_t>(t));
        }
    }
    stats_.uncovered_triangles = uncovered_.size();
    if (!uncovered_.empty()) {
        const Buffer<uint32_t> list(context_, uncovered_, "decomp_uncovered");
        context_.launch(kernel("decomp_radiosity_traced"), uncovered_.size(), params_,
                        SceneArguments(bvh_, device_scene_), triangle_buffer_, list, traced_samples,
                        in->traced, in->counters);
    }
}

void IrradianceDecomposition::gather_pass(GatherInputs& in, const Buffer<shared::float4>& previous,
                                          bool with_near) {
    const unsigned near_flag = with_near ? 1u : 0u;
    context_.launch(kernel("decomp_radiosity_gather"), triangles_.size(), params_,
                    SceneArguments(bvh_, device_scene_), far_grid_.grid, far_start_, far_list_,
                    far_records_, far_coefficients_, far_gradients_, near_grid_.grid, near_start_,
                    near_list_, triangle_buffer_, in.direct, in.reflectance, in.covered, in.traced,
                    previous, near_flag, radiance_buffer_, in.counters);
}

std::vector<shared::ClusterFit> IrradianceDecomposition::fit_batch(
    const std::vector<PendingCluster>& batch, std::vector<shared::ClusterRay>* rays) {
    std::vector<shared::DecompCluster> clusters;
    std::vector<uint32_t> members;
    for (const PendingCluster& p : batch) {
        shared::DecompCluster c{};
        c.centre = float4_of(p.cluster.centre);
        c.test_radius = split_factor_ * p.cluster.radius;
        c.first_member = static_cast<uint32_t>(members.size());
        c.member_count = static_cast<uint32_t>(p.cluster.members.size());
        c.stream = p.stream;
        clusters.push_back(c);
        members.insert(members.end(), p.cluster.members.begin(), p.cluster.members.end());
    }
    if (cluster_split_ && rays == nullptr) {
        uint64_t traced = 0;
        std::vector<shared::ClusterFit> fits =
            cluster_split_->fit_batch(params_, clusters, members, &traced);
        stats_.cluster_rays += traced;
        return fits;
    }
    const size_t ray_count = batch.size() * static_cast<size_t>(params_.cluster_rays);
    const Buffer<shared::DecompCluster> cluster_buffer(context_, clusters, "decomp_clusters");
    const Buffer<uint32_t> member_buffer(context_, members, "decomp_members");
    Buffer<shared::ClusterRay> ray_buffer(context_, ray_count, "decomp_cluster_rays");
    Buffer<shared::ClusterFit> fit_buffer(context_, batch.size(), "decomp_fits");
    Buffer<unsigned> counters(context_, 1, "decomp_cluster_counters");
    counters.fill_zero();
    if (radiosity_source_) {
        context_.launch(kernel("decomp_cluster_hits"), ray_count, params_,
                        SceneArguments(bvh_, device_scene_), split_nodes_, split_roots_,
                        cluster_buffer, member_buffer, gbuffer_, ray_buffer, counters);
    } else {
        context_.launch(kernel("decomp_cluster_rays"), ray_count, params_,
                        SceneArguments(bvh_, device_scene_), *source_, cluster_buffer,
                        member_buffer, gbuffer_, ray_buffer, counters);
    }
    context_.launch(kernel("decomp_fit"), batch.size(), params_, ray_buffer, fit_buffer);
    stats_.cluster_rays += counters.download()[0];
    if (rays != nullptr) {
        *rays = ray_buffer.download();
    }
    return fit_buffer.download();
}

// §4.1: clusters of the camera samples (the first of each pixel), split in two while their rays
// see a surface inside their bounding sphere and they are at least alpha across; each cluster
// that stays whole gives a far-field sample.
void IrradianceDecomposition::sample_far_field(const DecompositionOptions& options) {
    far_.clear();
    far_rays_.clear();
    cluster_split_.reset();
    if (frame_devices(frame_) > 1 && !radiosity_source_ &&
        dynamic_cast<const PathContinuation*>(source_) != nullptr) {
        cluster_split_ = std::make_unique<DecompClusterSplit>(frame_, gbuffer_, samples_,
                                                              source_->build_options());
    }
    ShadingPoints points;
    std::vector<uint32_t> members;
    for (size_t i = 0; i < samples_.size(); ++i) {
        points.positions.push_back(vec3_of(samples_[i].position));
        points.normals.push_back(vec3_of(samples_[i].normal));
        if (samples_[i].served != 0 && i % static_cast<size_t>(params_.camera_spp) == 0) {
            members.push_back(static_cast<uint32_t>(i));
        }
    }
    stats_.clustered_points = members.size();
    std::deque<PendingCluster> pending;
    if (!members.empty()) {
        pending.push_back({make_cluster(points, std::move(members)), 0});
    }
    uint32_t next_stream = 1;
    const size_t batch_limit =
        std::max<size_t>(1, kMaxBatchRays / static_cast<size_t>(options.cluster_rays));
    while (!pending.empty()) {
        std::vector<PendingCluster> batch;
        while (!pending.empty() && batch.size() < batch_limit) {
            batch.push_back(std::move(pending.front()));
            pending.pop_front();
        }
        std::vector<shared::ClusterRay> rays;
        const std::vector<shared::ClusterFit> fits =
            fit_batch(batch, radiosity_source_ ? &rays : nullptr);
        stats_.clusters_sampled += batch.size();
        for (size_t b = 0; b < batch.size(); ++b) {
            const PointCluster& c = batch[b].cluster;
            if (needs_split(c, fits[b].inside, options.min_cluster_size,
                            static_cast<uint32_t>(options.min_cluster))) {
                auto halves = split_in_two(points, c);
                if (!halves.second.empty()) {
                    pending.push_back(
                        {make_cluster(points, std::move(halves.first)), next_stream++});
                    pending.push_back(
                        {make_cluster(points, std::move(halves.second)), next_stream++});
                    continue;
                }
            }
            double footprints = 0.0;
            for (uint32_t m : c.members) {
                footprints += samples_[m].footprint;
            }
            const float footprint = static_cast<float>(footprints / c.members.size());
            FarSample s;
            s.centre = c.centre;
            s.normal = c.normal;
            s.radius = c.radius;
            s.reach = kReach * std::max(c.radius, kMinRadiusFootprints * footprint);
            s.members = static_cast<uint32_t>(c.members.size());
            s.kept_rays = fits[b].kept;
            s.sh = fits[b].sample;
            s.gradient = fits[b].gradient;
            far_.push_back(s);
            if (radiosity_source_) {
                const auto first = rays.begin() + static_cast<ptrdiff_t>(b * params_.cluster_rays);
                far_rays_.insert(far_rays_.end(), first, first + params_.cluster_rays);
            }
        }
    }
    stats_.sh_samples = far_.size();
    build_far_grid();
}

void IrradianceDecomposition::build_far_grid() {
    std::vector<glm::vec3> centres;
    std::vector<float> reach;
    std::vector<glm::vec3> normals;
    std::vector<shared::ShSample> coefficients;
    std::vector<shared::ShGradient> gradients;
    for (const FarSample& s : far_) {
        centres.push_back(s.centre);
        normals.push_back(s.normal);
        reach.push_back(s.reach);
        coefficients.push_back(s.sh);
        gradients.push_back(s.gradient);
    }
    const std::vector<shared::Record> records = reach_records(centres, reach, normals);
    far_grid_ = build_record_grid(records, 1.0f);
    far_start_ = Buffer<int>(context_, far_grid_.cell_start, "decomp_far_start");
    far_list_ = Buffer<int>(context_, far_grid_.cell_records, "decomp_far_list");
    far_records_ = Buffer<shared::Record>(context_, records, "decomp_far_records");
    far_coefficients_ = Buffer<shared::ShSample>(context_, coefficients, "decomp_far_sh");
    far_gradients_ = Buffer<shared::ShGradient>(context_, gradients, "decomp_far_gradients");
}

Buffer<shared::DecompIrradiance> IrradianceDecomposition::evaluate(
    const Buffer<shared::GBufferSample>& points, size_t count) {
    Buffer<shared::DecompIrradiance> out(context_, count, "decomp_irradiance");
    context_.launch(kernel("decomp_irradiance"), count, params_,
                    SceneArguments(bvh_, device_scene_), points, far_grid_.grid, far_start_,
                    far_list_, far_records_, far_coefficients_, far_gradients_, near_grid_.grid,
                    near_start_, near_list_, triangle_buffer_, radiance_buffer_, out);
    return out;
}

std::vector<shared::float4> IrradianceDecomposition::shade(
    const Buffer<shared::DecompIrradiance>& irradiance) {
    const size_t pixels = static_cast<size_t>(params_.width) * params_.height;
    Buffer<shared::float4> film(context_, pixels * RC_DECOMP_FILM_SLOTS, "decomp_film");
    Buffer<unsigned> counters(context_, 3, "decomp_counters");
    counters.upload({0u, 0u, 0xffffffffu});
    context_.launch(kernel("decomp_shade"), pixels, params_, camera_,
                    SceneArguments(bvh_, device_scene_), irradiance, film, counters);
    std::vector<shared::float4> sums = film.download();
    const std::vector<unsigned> c = counters.download();
    stats_.shading_rays += c[0];
    stats_.nonfinite_samples = c[1];
    stats_.first_nonfinite_pixel = c[1] > 0 ? static_cast<int64_t>(c[2]) : -1;
    return sums;
}

namespace {

// The figures of the evaluation: near triangles and far-field samples per served camera sample.
void add_evaluation_stats(const std::vector<shared::DecompIrradiance>& terms,
                          const std::vector<shared::GBufferSample>& samples,
                          DecompositionStats* stats) {
    uint64_t near = 0;
    uint64_t far = 0;
    uint64_t rays = 0;
    for (size_t i = 0; i < terms.size(); ++i) {
        if (samples[i].served == 0) {
            continue;
        }
        ++stats->served_samples;
        near += terms[i].near_count;
        rays += terms[i].near_rays;
        far += terms[i].far_samples;
        stats->near_max = std::max(stats->near_max, terms[i].near_count);
        stats->far_uncovered += terms[i].far_samples == 0 ? 1 : 0;
    }
    const double served = static_cast<double>(std::max<size_t>(stats->served_samples, 1));
    stats->near_mean = static_cast<double>(near) / served;
    stats->far_mean = static_cast<double>(far) / served;
    stats->near_rays = rays;
}

}  // namespace

// Pass 2 (§6): both terms at every camera sample, then the render pass; with several devices in
// chunks of rows shared among them (decomp_device_split.h). The film's sums.
std::vector<shared::float4> IrradianceDecomposition::pass_two(size_t samples) {
    auto start = SteadyClock::now();
    if (frame_devices(frame_) > 1) {
        const DecompFields fields{far_grid_,        far_start_,        far_list_,
                                  far_records_,     far_coefficients_, far_gradients_,
                                  near_grid_,       near_start_,       near_list_,
                                  triangle_buffer_, radiance_buffer_};
        DecompPassOutput out = decomp_device_pass(
            frame_, {params_, camera_, source_->build_options(), gbuffer_, samples_, fields});
        add_evaluation_stats(out.terms, samples_, &stats_);
        stats_.evaluation_seconds = seconds_since(start);
        stats_.shading_rays += out.shading_rays;
        stats_.nonfinite_samples = out.nonfinite_samples;
        stats_.first_nonfinite_pixel = out.first_nonfinite_pixel;
        stats_.devices = std::move(out.shares);
        for (size_t d = 0; d < radiosity_shares_.size() && d < stats_.devices.size(); ++d) {
            stats_.devices[d].radiosity_triangles = radiosity_shares_[d].triangles;
            stats_.devices[d].radiosity_rays = radiosity_shares_[d].rays;
            stats_.devices[d].radiosity_seconds = radiosity_shares_[d].seconds;
        }
        for (size_t d = 0; cluster_split_ && d < stats_.devices.size(); ++d) {
            const DecompClusterShare& share = cluster_split_->shares()[d];
            stats_.devices[d].cluster_ranges = share.cluster_ranges;
            stats_.devices[d].clusters = share.clusters;
            stats_.devices[d].cluster_rays = share.cluster_rays;
            stats_.devices[d].cluster_seconds = share.seconds;
        }
        return std::move(out.film);
    }
    const Buffer<shared::DecompIrradiance> terms = evaluate(gbuffer_, samples);
    add_evaluation_stats(terms.download(), samples_, &stats_);
    stats_.evaluation_seconds = seconds_since(start);
    start = SteadyClock::now();
    std::vector<shared::float4> sums = shade(terms);
    stats_.shading_seconds = seconds_since(start);
    return sums;
}

Image IrradianceDecomposition::render(const DecompositionOptions& options,
                                      DecompositionStats* stats) {
    const int width = options.width > 0 ? options.width : scene_.camera.width;
    const int height = options.height > 0 ? options.height : scene_.camera.height;
    const int evaluated_spp = std::max(options.spp, options.indirect_spp);
    const size_t samples =
        static_cast<size_t>(width) * height * static_cast<size_t>(std::max(evaluated_spp, 0));
    check_options(options, samples);
    source_ = options.source;
    radiosity_source_ = options.radiosity_source;
    reach_needed_ = options.radiosity_source;
    split_factor_ = options.split_factor;
    stats_ = DecompositionStats{};
    radiosity_shares_.clear();
    params_ = shared::DecompParams{};
    params_.width = width;
    params_.height = height;
    params_.camera_spp = evaluated_spp;
    params_.shaded_spp = options.spp;
    params_.light_samples = options.light_samples;
    set_kernel_path_settings(options, &params_);
    params_.cluster_rays = options.cluster_rays;
    params_.radiosity_samples = options.radiosity_samples;
    params_.alpha = options.alpha;
    params_.ridge = kRidge;
    params_.count_emission = options.count_emission ? 1 : 0;
    params_.near_visibility = options.visibility_rays ? 1 : 0;
    params_.gradients = options.gradients ? 1 : 0;
    params_.gradient_ridge = kGradientRidge;
    params_.near_set = options.near_touching ? RC_DECOMP_NEAR_TOUCHING : RC_DECOMP_NEAR_CENTROID;
    camera_ = camera_params(scene_.camera, width, height);

    auto start = SteadyClock::now();
    compute_gbuffer();
    stats_.gbuffer_seconds = seconds_since(start);
    // Pass 1 (§6): the near field's triangles and radiosity, the far field's samples.
    start = SteadyClock::now();
    build_near_field(options);
    if (options.radiosity_passes == 0) {
        std::vector<uint32_t> every(triangles_.size());
        for (size_t t = 0; t < every.size(); ++t) {
            every[t] = static_cast<uint32_t>(t);
        }
        coarse_radiosity(every, radiance_buffer_);
    }
    context_.finish();
    stats_.near_seconds = seconds_since(start);
    start = SteadyClock::now();
    sample_far_field(options);
    stats_.far_seconds = seconds_since(start);
    if (options.radiosity_source) {
        start = SteadyClock::now();
        iterate_radiosity_source(options.source_iterations, options.source_extrapolate,
                                 options.traced_samples);
        context_.finish();
        stats_.near_seconds += seconds_since(start);
    } else if (options.radiosity_passes > 0) {
        start = SteadyClock::now();
        gather_radiosity(options.radiosity_passes, options.traced_samples);
        context_.finish();
        stats_.near_seconds += seconds_since(start);
    }
    Image image = decomposition_image(pass_two(samples), width, height);
    if (stats != nullptr) {
        *stats = stats_;
    }
    return image;
}

Image IrradianceDecomposition::render_samples(int first, int spp, DecompositionStats* stats) {
    if (source_ == nullptr) {
        throw Error("internal: irradiance decomposition: render_samples before render");
    }
    if (spp < 1 || first < 0 ||
        static_cast<int64_t>(first) + spp > std::numeric_limits<int32_t>::max()) {
        throw Error("irradiance decomposition: camera samples " + std::to_string(first) + " + " +
                        std::to_string(spp) + " out of range",
                    kExitUsage);
    }
    const size_t samples =
        static_cast<size_t>(params_.width) * params_.height * static_cast<size_t>(spp);
    if (samples > std::numeric_limits<uint32_t>::max()) {
        throw Error("irradiance decomposition: width x height x spp exceeds 2^32 camera samples",
                    kExitUsage);
    }
    // The fields' sizes stay; the pass's own figures start from zero.
    DecompositionStats pass;
    pass.scene_triangles = stats_.scene_triangles;
    pass.near_triangles = stats_.near_triangles;
    pass.clustered_points = stats_.clustered_points;
    pass.sh_samples = stats_.sh_samples;
    pass.radiosity_passes = stats_.radiosity_passes;
    pass.uncovered_triangles = stats_.uncovered_triangles;
    stats_ = pass;
    // The shares of building the fields were render()'s.
    radiosity_shares_.clear();
    cluster_split_.reset();
    params_.camera_spp = spp;
    params_.shaded_spp = spp;
    params_.first_sample = first;
    const auto start = SteadyClock::now();
    compute_gbuffer();
    stats_.gbuffer_seconds = seconds_since(start);
    Image image = decomposition_image(pass_two(samples), params_.width, params_.height);
    if (stats != nullptr) {
        *stats = stats_;
    }
    return image;
}

std::vector<glm::vec3> IrradianceDecomposition::near_radiance() const {
    std::vector<glm::vec3> out;
    for (const shared::float4& r : radiance_buffer_.download()) {
        out.push_back(vec3_of(r));
    }
    out.resize(triangles_.size());
    return out;
}

std::vector<shared::DecompIrradiance> IrradianceDecomposition::irradiance_at(
    const std::vector<shared::GBufferSample>& points) {
    const Buffer<shared::GBufferSample> buffer(context_, points, "decomp_points");
    return evaluate(buffer, points.size()).download();
}

std::vector<shared::ClusterRay> IrradianceDecomposition::cluster_rays(
    const std::vector<uint32_t>& members, uint32_t stream) {
    PendingCluster p;
    ShadingPoints points;
    for (const shared::GBufferSample& g : samples_) {
        points.positions.push_back(vec3_of(g.position));
        points.normals.push_back(vec3_of(g.normal));
    }
    p.cluster = make_cluster(points, members);
    p.stream = stream;
    std::vector<shared::ClusterRay> rays;
    fit_batch({p}, &rays);
    return rays;
}

}  // namespace rc
