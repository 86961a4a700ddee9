// --decomp-source radiosity: the far field's rays read the split triangles' own radiosity B(t)
// (the paper, §4: "Wherever these rays hit, we lookup the proxy global illumination"; §6: the
// coarse solution is per-triangle radiosity). B(t) is gathered from the far field, which reads
// B(t): the rays are traced once while the clusters are built (their split only needs the hits),
// and then B(t) and the far-field fits are iterated with no further ray (docs/decomposition.md,
// "The split triangles' radiosity as the far field's source").
#include <algorithm>
#include <cmath>

#include "methods/decomposition/decomposition.h"
#include "methods/scene_arguments.h"
#include "util/glm_helpers.h"

namespace rc {
namespace {

// Area-weighted luminance of each split triangle's B(t) / pi.
std::vector<double> weighted_luminance(const std::vector<shared::NearTriangle>& triangles,
                                       const std::vector<shared::float4>& radiance) {
    std::vector<double> out(triangles.size());
    for (size_t t = 0; t < triangles.size(); ++t) {
        const glm::vec3 e1 = vec3_of(triangles[t].v1) - vec3_of(triangles[t].v0);
        const glm::vec3 e2 = vec3_of(triangles[t].v2) - vec3_of(triangles[t].v0);
        const double area = 0.5 * glm::length(glm::cross(e1, e2));
        const shared::float4& r = radiance[t];
        out[t] = area * (0.2126 * r.x + 0.7152 * r.y + 0.0722 * r.z);
    }
    return out;
}

// sum |b - a| / sum |b|.
double relative_change(const std::vector<double>& a, const std::vector<double>& b) {
    double difference = 0.0;
    double total = 0.0;
    for (size_t t = 0; t < a.size(); ++t) {
        difference += std::fabs(b[t] - a[t]);
        total += std::fabs(b[t]);
    }
    return total > 0.0 ? difference / total : 0.0;
}

// The largest ratio of successive changes the tail is extrapolated with (a tail of at most 9
// times the last change).
constexpr double kMaxTailRatio = 0.9;

// The bounces the iteration left out, added as a geometric tail (the ambient term of progressive
// radiosity: Cohen, Chen, Wallace and Greenberg, "A Progressive Refinement Approach to Fast
// Radiosity Image Generation", SIGGRAPH 1988, §4, estimates the unshot light from the mean
// reflectance; here the ratio is measured): Jacobi iteration of B = E + T B converges along T's
// dominant eigenvector, each step's change about `ratio` times the last, so what remains after
// B^K is about (B^K - B^(K-1)) ratio / (1 - ratio). `ratio` is the last two iterations'
// relative changes' ratio, at most kMaxTailRatio; none below 2 iterations or when it is not
// below 1. Returns the ratio used (0: none); `now` (B^K / pi) is replaced by the extrapolated,
// never negative.
double extrapolate_bounce_tail(const std::vector<double>& change,
                               const std::vector<shared::float4>& before,
                               std::vector<shared::float4>* now) {
    const size_t n = change.size();
    if (n < 2 || !(change[n - 2] > 0.0) || !(change[n - 1] < change[n - 2])) {
        return 0.0;
    }
    const double ratio = std::min(change[n - 1] / change[n - 2], kMaxTailRatio);
    const double tail = ratio / (1.0 - ratio);
    auto extend = [tail](float b, float a) {
        return static_cast<float>(std::max(0.0, b + tail * (static_cast<double>(b) - a)));
    };
    for (size_t t = 0; t < now->size(); ++t) {
        shared::float4& b = (*now)[t];
        b = {extend(b.x, before[t].x), extend(b.y, before[t].y), extend(b.z, before[t].z), b.w};
    }
    return ratio;
}

}  // namespace

// Every far-field sample refitted (decomp_fit) to its traced rays with the radiance B(t) / pi of
// `radiance` at their hits; its grid's coefficients replaced.
void IrradianceDecomposition::refit_far_field(const Buffer<shared::float4>& radiance) {
    const size_t ray_count = far_rays_.size();
    Buffer<shared::ClusterRay> rays(context_, ray_count, "decomp_radiosity_rays");
    context_.launch(kernel("decomp_radiosity_rays"), ray_count, far_ray_buffer_, radiance, rays);
    Buffer<shared::ClusterFit> fits(context_, far_.size(), "decomp_fits");
    context_.launch(kernel("decomp_fit"), far_.size(), params_, rays, fits);
    const std::vector<shared::ClusterFit> fitted = fits.download();
    for (size_t i = 0; i < far_.size(); ++i) {
        far_[i].sh = fitted[i].sample;
        far_[i].gradient = fitted[i].gradient;
    }
    build_far_grid();
}

void IrradianceDecomposition::iterate_radiosity_source(int iterations, bool extrapolate,
                                                       int traced_samples) {
    stats_.radiosity_passes = iterations;
    if (triangles_.empty() || far_.empty()) {
        return;
    }
    far_ray_buffer_ = Buffer<shared::ClusterRay>(context_, far_rays_, "decomp_far_rays");
    for (const shared::ClusterRay& r : far_rays_) {
        stats_.source_rays_without_triangle += r.kept != 0 && r.split_triangle < 0 ? 1 : 0;
    }
    GatherInputs inputs;
    prepare_gather(traced_samples, &inputs);
    // B^0: the direct part where the far field covers a triangle, path traced where it does not.
    std::vector<shared::float4> b0 = inputs.direct.download();
    const std::vector<shared::float4> traced = inputs.traced.download();
    for (uint32_t t : uncovered_) {
        b0[t] = traced[t];
    }
    radiance_buffer_.upload(b0);
    // B^(k-1) and B^k on the host: the change's luminance and the tail read them.
    std::vector<shared::float4> before = std::move(b0);
    std::vector<double> last = weighted_luminance(triangles_, before);
    Buffer<shared::float4> previous(context_, triangles_.size(), "decomp_radiance_previous");
    for (int k = 1; k <= iterations; ++k) {
        refit_far_field(radiance_buffer_);
        std::swap(previous, radiance_buffer_);
        gather_pass(inputs, previous, true);
        std::vector<shared::float4> radiance = radiance_buffer_.download();
        std::vector<double> now = weighted_luminance(triangles_, radiance);
        stats_.source_change.push_back(relative_change(last, now));
        last = std::move(now);
        if (k < iterations) {
            before = std::move(radiance);
        } else if (extrapolate) {
            stats_.source_tail_ratio =
                extrapolate_bounce_tail(stats_.source_change, before, &radiance);
            radiance_buffer_.upload(radiance);
        }
    }
    refit_far_field(radiance_buffer_);
    stats_.radiosity_rays += inputs.counters.download()[0];
}

}  // namespace rc
