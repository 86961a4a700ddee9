// Pixel reconstruction filters by filter importance sampling (Ernst, Stamminger and Greiner,
// "Filter Importance Sampling", IEEE RT 2006; pbrt-v4 §8.8.1 and §5.4.3, "FilterSampler"): the
// offset of a camera sample from its pixel's centre is drawn from the pixel's filter, separably
// along x and y, so that every sample counts with weight 1 in its own pixel's mean and in no other
// pixel. A pixel's mean then estimates the filter-weighted integral of the image around its
// centre, its samples stay independent (the stddev layer and relMSE net of noise hold), and no
// pixel reads another's samples (nothing to splat, no atomics). docs/pixel-filters.md.
#pragma once

#include "common/math.h"
#include "shared/types.h"

// The Gaussian filter's standard deviation: a third of its radius (pbrt-v4's defaults, radius
// 1.5 and sigma 0.5, have that ratio).
RC_FUNC float rc_gaussian_filter_sigma(float radius) { return radius / 3.0f; }

// The Gaussian filter along one axis: exp(-t^2 / (2 sigma^2)) - exp(-radius^2 / (2 sigma^2)) on
// [-radius, radius] (pbrt-v4's GaussianFilter, §8.8.4: shifted to reach 0 at the radius), with
// the constants of its integral.
typedef struct GaussianFilter {
    float radius;
    float scale;        // sigma sqrt(2)
    float lead;         // sigma sqrt(pi / 2)
    float erf_radius;   // erf(radius / scale)
    float floor_value;  // exp(-radius^2 / (2 sigma^2))
} GaussianFilter;

RC_FUNC GaussianFilter rc_gaussian_filter(float radius) {
    const float sigma = rc_gaussian_filter_sigma(radius);
    GaussianFilter g;
    g.radius = radius;
    g.scale = sigma * sqrt(2.0f);
    g.lead = sigma * sqrt(0.5f * RC_PI);
    g.erf_radius = erf(radius / g.scale);
    g.floor_value = exp(-radius * radius / (2.0f * sigma * sigma));
    return g;
}

// The filter's integral over [-radius, x].
RC_FUNC float rc_gaussian_filter_cdf(const GaussianFilter* g, float x) {
    return g->lead * (erf(x / g->scale) + g->erf_radius) - g->floor_value * (x + g->radius);
}

// The filter's value at x.
RC_FUNC float rc_gaussian_filter_value(const GaussianFilter* g, float x) {
    return exp(-(x * x) / (g->scale * g->scale)) - g->floor_value;
}

// The offset in [-radius, radius] where the Gaussian filter's distribution reaches u: its CDF
// inverted by 4 bisection steps, then 6 Newton steps kept inside the bracket (a step leaving it
// bisects instead); a fixed count, so every device gives the same offset.
RC_FUNC float rc_gaussian_filter_offset(float radius, float u) {
    const GaussianFilter g = rc_gaussian_filter(radius);
    const float target = u * rc_gaussian_filter_cdf(&g, radius);
    float lo = -radius;
    float hi = radius;
    float x = 0.0f;
    for (int step = 0; step < 10; ++step) {
        const float error = rc_gaussian_filter_cdf(&g, x) - target;
        if (error < 0.0f) {
            lo = x;
        } else {
            hi = x;
        }
        const float slope = rc_gaussian_filter_value(&g, x);
        const float newton = x - error / slope;
        x = (step >= 4 && slope > 0.0f && newton > lo && newton < hi) ? newton : 0.5f * (lo + hi);
    }
    return x;
}

// The offset along one axis, in pixels from the pixel's centre, of a sample drawn from the
// filter with u in [0, 1): box, uniform on [-radius, radius]; tent, max(0, radius - |x|) by
// inverting its CDF on either side of 0; Gaussian by bisection.
RC_FUNC float rc_filter_offset(int filter, float radius, float u) {
    if (filter == RC_FILTER_TENT) {
        return radius * (u < 0.5f ? sqrt(2.0f * u) - 1.0f : 1.0f - sqrt(2.0f - 2.0f * u));
    }
    if (filter == RC_FILTER_GAUSSIAN) {
        return rc_gaussian_filter_offset(radius, u);
    }
    return radius * (2.0f * u - 1.0f);
}

// The image position (pixels, (0, 0) the top-left corner) of a camera sample of `pixel` drawn
// with (u, v) in [0, 1)^2. The box filter of radius 0.5 gives (x + u, y + v) exactly (every step
// but the last sum is exact), the jitter every method drew before filters.
RC_FUNC float2 rc_filter_sample_position(const CameraParams* camera, uint pixel, float u, float v) {
    const uint px = pixel % (uint)camera->resolution.x;
    const uint py = pixel / (uint)camera->resolution.x;
    return (float2)((float)px + 0.5f + rc_filter_offset(camera->filter, camera->filter_radius, u),
                    (float)py + 0.5f + rc_filter_offset(camera->filter, camera->filter_radius, v));
}
