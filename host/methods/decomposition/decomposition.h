// Irradiance decomposition on the device (DESIGN.md §6.6b; `radcache render --method
// decomposition`; Arikan, Forsyth and O'Brien, "Fast and Detailed Approximate Global Illumination
// by Irradiance Decomposition", SIGGRAPH 2005, and the course's chapter "Irradiance
// Decomposition"). The irradiance at a shading point is split at a distance alpha (eq. 3):
// B = rho / pi (I_D + I_N). The distant term I_D comes from spherical-harmonic samples of the
// distant incident radiance L_D*, one per cluster of shading points, fitted to rays that ignore
// hits nearer than alpha and interpolated (§4); the near correction I_N of eq. 4 is computed at
// every shading point from the triangles within alpha, their form factors and coarse
// radiosities, with the paper's visibility heuristic and no rays (§5). The coarse solution is a
// radiance source (the irradiance vector grid). The algorithm (§6): a G-buffer of camera samples;
// pass 1, the triangles split to alpha and their radiosity, the clusters and their fits; pass 2,
// both terms at every camera sample and the render pass. Owns its buffers; reports its
// statistics.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "device/buffer.h"
#include "image/image.h"
#include "methods/caching/record_grid.h"
#include "methods/decomposition/decomp_device_split.h"
#include "methods/decomposition/decomp_radiosity_split.h"
#include "methods/frame_scene.h"
#include "methods/radiance_source.h"
#include "methods/shared_settings.h"
#include "shared/decomposition.h"
#include "shared/types.h"

namespace rc {

class DecompClusterSplit;

struct DecompositionOptions : SharedSettings {  // spp: camera samples shaded fully
    DecompositionOptions() { spp = 4; }
    // Camera samples per pixel where the two terms are evaluated (--decomp-indirect-spp; 0: spp):
    // the first spp of them shaded fully, the others only for the diffuse lobe's indirect light.
    int indirect_spp = 0;
    float alpha = 0.0f;  // the near/far distance, scene units (0: no near field)
    // A cluster less than this across is not split (--decomp-cluster, scene units; the paper's
    // rule: alpha).
    float min_cluster_size = 0.0f;
    int cluster_rays = 512;  // rays per cluster's fit (§4.1: 512)
    // §4.1's split test looks for hits inside the cluster's bounding sphere scaled by this
    // (--decomp-split; the paper's test: 1).
    float split_factor = 4.0f;
    int min_cluster = 16;       // a cluster of fewer than 2 min_cluster points is not split
    int light_samples = 4;      // the render pass's light samples per camera hit
    int radiosity_samples = 4;  // points per split triangle of its radiosity
    // B(t) gathered from the decomposition's own two terms at the split triangles
    // (--decomp-radiosity gathered, the default; decomp_radiosity.h) in this many passes, the
    // first with I_N = 0, each further one a Jacobi step of the near triangles' exchange; 0: read
    // from the coarse solution (--decomp-radiosity coarse).
    int radiosity_passes = 3;
    // Gathered: points per split triangle of the path-traced B(t) of those no far-field sample
    // covers.
    int traced_samples = 16;
    bool count_emission = false;  // rays count the emission they see (tests)
    // Test each near triangle that passes the paper's heuristic with a shadow ray to its centroid
    // (--decomp-visibility rays) instead of taking it as visible.
    bool visibility_rays = false;
    // The near set of eq. 4: the split triangles with any point within alpha (--decomp-near
    // touching, the default with the gathered radiosity), or those whose centroid lies within
    // alpha (centroid, the paper's; the default with the coarse radiosity;
    // kernels/decomposition/decomp_near_set.h; measured in docs/decomposition.md).
    bool near_touching = true;
    // Fit each far-field sample's translational gradient with its coefficients and interpolate
    // with it (--decomp-gradients on, the default; rc_decomp_fit_with_gradients; measured in
    // docs/decomposition.md).
    bool gradients = true;
    // The coarse solution the rays read at their hits (the method's: the irradiance vector grid;
    // path continuation in tests); required. With radiosity_source, the program's source (the
    // split triangles' path-traced B(t) reads none of it).
    const RadianceSource* source = nullptr;
    // --decomp-source radiosity: the cluster rays read the gathered radiosity B(t) / pi of the
    // split triangle they hit (decomp_radiosity_source.cpp), refitted over `source_iterations`
    // iterations of B(t) with no ray; needs alpha > 0 and the gathered radiosity.
    bool radiosity_source = false;
    int source_iterations = 4;
    // With radiosity_source and at least 2 iterations: the bounces left after the last one added
    // as a geometric tail (decomp_radiosity_source.cpp, extrapolate_bounce_tail).
    bool source_extrapolate = true;
};

// One far-field sample (§4.1): the fit of a cluster that needed no split.
struct FarSample {
    glm::vec3 centre{0.0f};  // where it is stored: its cluster's centre
    glm::vec3 normal{0.0f};  // its cluster's mean normal (shorter than 1 for mixed orientations)
    float radius = 0.0f;     // its cluster's bounding radius
    float reach = 0.0f;      // it is interpolated at points within this distance
    uint32_t members = 0;    // its cluster's shading points
    uint32_t kept_rays = 0;  // its rays that entered the fit
    shared::ShSample sh{};
    shared::ShGradient gradient{};  // all zero without gradients
};

// Error (exit status 2) unless --decomp-indirect-spp is 0 (--spp's) or at least --spp.
void check_indirect_spp(const DecompositionOptions& options);

struct DecompositionStats {
    size_t scene_triangles = 0;
    size_t near_triangles = 0;    // after splitting to alpha
    size_t clustered_points = 0;  // shading points the clusters partition
    size_t clusters_sampled = 0;  // clusters whose rays were traced (split ones included)
    size_t sh_samples = 0;        // far-field samples
    size_t served_samples = 0;    // camera samples whose diffuse lobe the decomposition serves
    double near_mean = 0.0;       // near triangles per served camera sample
    uint32_t near_max = 0;
    double far_mean = 0.0;           // far-field samples with a positive weight per served sample
    size_t far_uncovered = 0;        // served samples no far-field sample reached (nearest used)
    uint64_t radiosity_rays = 0;     // the split triangles' radiosity (every pass)
    int radiosity_passes = 0;        // gathered passes (0: from the coarse solution)
    size_t uncovered_triangles = 0;  // gathered: facing away from the far field (B(t) traced)
    uint64_t cluster_rays = 0;       // the clusters' fits (and the source's rays for them)
    // --decomp-source radiosity: per iteration k, sum |B^k - B^(k-1)| / sum |B^k| over the split
    // triangles (luminance of B(t) / pi, area-weighted), and the kept rays that hit a split
    // triangle's back face or missed (they bring back no radiosity).
    std::vector<double> source_change;
    uint64_t source_rays_without_triangle = 0;
    double source_tail_ratio = 0.0;  // the ratio the tail was extrapolated with (0: none)
    uint64_t near_rays = 0;          // shadow rays of the near field (--decomp-visibility rays)
    uint64_t shading_rays = 0;       // the G-buffer and the render pass
    double gbuffer_seconds = 0.0;
    double near_seconds = 0.0;        // splitting, the near triangles' grid, their radiosity
    double far_seconds = 0.0;         // clusters, their rays and fits, the samples' grid
    double evaluation_seconds = 0.0;  // both terms at every camera sample (several devices:
                                      // and the render pass, chunk by chunk)
    double shading_seconds = 0.0;     // the render pass (0 with several devices: in evaluation)
    uint64_t nonfinite_samples = 0;
    int64_t first_nonfinite_pixel = -1;
    // With several devices: each one's share of pass 2 (decomp_device_split.h).
    std::vector<DecompDeviceShare> devices;
};

// The layers of a decomposed image, in channel order (3 channels each): beauty (R, G, B),
// direct, indirect, albedo, normal, far-field (rho_d / pi I_D), near-field (rho_d / pi I_N,
// signed).
extern const char* const kDecompositionAovs[7];

class IrradianceDecomposition : private FrameBound {
   public:
    explicit IrradianceDecomposition(const FrameScene& frame);
    ~IrradianceDecomposition();

    Image render(const DecompositionOptions& options, DecompositionStats* stats = nullptr);
    // After render(): camera samples first .. first + spp - 1 of every pixel (the samples one
    // render of first + spp would draw them), all shaded fully, over render()'s near and far
    // fields (not rebuilt): their G-buffer, both terms at each one and the render pass. *stats:
    // the fields' sizes as render()'s, the rest this pass's own (no radiosity or cluster rays).
    Image render_samples(int first, int spp, DecompositionStats* stats = nullptr);

    // After render(): its camera samples (entry pixel * spp + s), far-field samples, split
    // triangles and their B(t) / pi.
    const std::vector<shared::GBufferSample>& camera_samples() const { return samples_; }
    const std::vector<FarSample>& far_samples() const { return far_; }
    const std::vector<shared::NearTriangle>& near_triangles() const { return triangles_; }
    std::vector<glm::vec3> near_radiance() const;
    // After a gathered render(): the split triangles whose B(t) was path traced.
    const std::vector<uint32_t>& uncovered_triangles() const { return uncovered_; }

    // After render(): I_D and I_N at G-buffer-like points from its far and near fields.
    std::vector<shared::DecompIrradiance> irradiance_at(
        const std::vector<shared::GBufferSample>& points);
    // After render(): the rays of a cluster of its camera samples (`members`: G-buffer entries)
    // with random stream `stream`.
    std::vector<shared::ClusterRay> cluster_rays(const std::vector<uint32_t>& members,
                                                 uint32_t stream);

   private:
    struct PendingCluster;
    // The gathered radiosity's buffers besides B(t).
    struct GatherInputs {
        Buffer<shared::float4> direct;       // what each sends besides its diffuse indirect light
        Buffer<shared::float4> reflectance;  // its diffuse reflectance
        Buffer<shared::float4> traced;       // path-traced B(t) / pi where uncovered
        Buffer<uint32_t> covered;            // 1 where a far-field sample covers it
        Buffer<unsigned> counters;           // [0]: rays
    };
    void compute_gbuffer();
    void build_near_field(const DecompositionOptions& options);
    void sample_far_field(const DecompositionOptions& options);
    // B(t) / pi of the split triangles from the source (coarse; of those listed, into
    // `radiance`) or gathered in `passes` passes (those no far-field sample covers path traced
    // at `traced_samples` points).
    void coarse_radiosity(const std::vector<uint32_t>& listed, Buffer<shared::float4>& radiance);
    void gather_radiosity(int passes, int traced_samples);
    // The gathered radiosity's inputs (direct part, reflectance, coverage, traced B(t)) and one
    // gathering pass reading `previous` (I_N from it when with_near) into radiance_buffer_.
    void prepare_gather(int traced_samples, GatherInputs* inputs);
    void gather_pass(GatherInputs& inputs, const Buffer<shared::float4>& previous, bool with_near);
    // --decomp-source radiosity (decomp_radiosity_source.cpp): B^0 (direct part; traced where
    // uncovered), then `iterations` times: the kept rays' radiance from B^(k-1), every far-field
    // sample refitted, B^k gathered; with `extrapolate` the bounces left added as a geometric
    // tail; the far field refitted from the last B(t).
    void iterate_radiosity_source(int iterations, bool extrapolate, int traced_samples);
    void refit_far_field(const Buffer<shared::float4>& radiance);
    // Rays and fits of a batch of clusters (their rays in *rays when given).
    std::vector<shared::ClusterFit> fit_batch(const std::vector<PendingCluster>& batch,
                                              std::vector<shared::ClusterRay>* rays = nullptr);
    void build_far_grid();
    Buffer<shared::DecompIrradiance> evaluate(const Buffer<shared::GBufferSample>& points,
                                              size_t count);
    std::vector<shared::float4> shade(const Buffer<shared::DecompIrradiance>& irradiance);
    std::vector<shared::float4> pass_two(size_t samples);
    Kernel& kernel(const char* name);

    FrameScene frame_;  // with its peers (several devices: pass 2 shared)
    // Several devices and path-traced continuation: the cluster batches shared.
    std::unique_ptr<DecompClusterSplit> cluster_split_;
    // The same: each device's share of the coarse radiosity (decomp_radiosity_split.h).
    std::vector<DecompRadiosityShare> radiosity_shares_;
    const RadianceSource* source_ = nullptr;
    float split_factor_ = 1.0f;
    shared::DecompParams params_{};
    shared::CameraParams camera_{};
    Buffer<shared::GBufferSample> gbuffer_;
    std::vector<shared::GBufferSample> samples_;
    std::vector<shared::NearTriangle> triangles_;
    std::vector<uint32_t> uncovered_;
    Buffer<shared::NearTriangle> triangle_buffer_;
    bool radiosity_source_ = false;
    bool reach_needed_ = false;
    Buffer<shared::SplitNode> split_nodes_;  // the scene triangles' split trees
    Buffer<uint32_t> split_roots_;
    // --decomp-source radiosity: the far-field samples' traced rays, far_'s order,
    // params_.cluster_rays each (on the host while the clusters are built, then on the device).
    std::vector<shared::ClusterRay> far_rays_;
    Buffer<shared::ClusterRay> far_ray_buffer_;
    Buffer<shared::float4> radiance_buffer_;
    RecordGridData near_grid_;
    Buffer<int> near_start_;
    Buffer<int> near_list_;
    std::vector<FarSample> far_;
    RecordGridData far_grid_;
    Buffer<int> far_start_;
    Buffer<int> far_list_;
    Buffer<shared::Record> far_records_;
    Buffer<shared::ShSample> far_coefficients_;
    Buffer<shared::ShGradient> far_gradients_;
    std::map<std::string, Kernel> kernels_;  // by name, from the program built for the source
    DecompositionStats stats_;
};

}  // namespace rc
