// A pixel of the caching methods' render passes (ic_shade, ivg_shade): its camera samples shaded
// by the method and their means written to the film (kernels/shared/film.h, RC_CACHED_FILM_*).
#pragma once

#include "common/cached_radiance.h"
#include "shared/film.h"

// What one camera sample gives the film: its light, the method's own layer
// (RC_CACHED_FILM_LAYER) and, where a method caches the glossy lobes (radiance caching), their
// indirect light, the order it used and the fraction of its directions a cache answered
// (RC_CACHED_FILM_GLOSSY, RC_CACHED_FILM_ORDER, RC_CACHED_FILM_HITS; 0 for the others).
typedef struct FilmSample {
    CachedRadiance light;
    float3 layer;
    float3 glossy;
    float order;
    float hits;  // RcGlossySample.hits
} FilmSample;

// The method's side of rc_shade_pixel: a render pass defines struct PixelShader (what its camera
// samples need) and rc_shade_camera_sample (camera sample s of a pixel) before its entry kernel.
typedef struct PixelShader PixelShader;
RC_FUNC FilmSample rc_shade_camera_sample(const PixelShader* shader, uint pixel, uint s);

// Adds a camera sample's light to a pixel's sums of beauty, direct, indirect, albedo and normal
// and its rays to *rays. A sample whose radiance is NaN or infinite is dropped instead and counted
// in counters[1], with the smallest such pixel in counters[2]. Returns whether the sample was
// added.
RC_FUNC bool rc_add_camera_sample(const CachedRadiance* l, float3 sums[RC_CACHED_FILM_SLOTS],
                                  uint* rays, RC_GLOBAL uint* counters, uint pixel) {
    const float3 radiance = l->direct + l->indirect;
    *rays += l->rays;
    if (!all(isfinite(radiance))) {
        atomic_inc(&counters[1]);
        atomic_min(&counters[2], pixel);
        return false;
    }
    sums[RC_CACHED_FILM_BEAUTY] += radiance;
    sums[RC_CACHED_FILM_DIRECT] += l->direct;
    sums[RC_CACHED_FILM_INDIRECT] += l->indirect;
    sums[RC_CACHED_FILM_ALBEDO] += l->albedo;
    sums[RC_CACHED_FILM_NORMAL] += l->normal;
    return true;
}

// Shades the pixel's `spp` camera samples and writes their means (over the finite ones) to its
// film slots; coverage is the smallest over the samples the cache serves (0 when one of them is
// uncovered or none is served). counters: [0] rays traced, [1] non-finite samples (dropped), [2]
// the first pixel that had one.
RC_FUNC void rc_shade_pixel(const PixelShader* shader, uint spp, uint pixel, RC_GLOBAL float4* film,
                            RC_GLOBAL uint* counters) {
    float3 sums[RC_CACHED_FILM_SLOTS];
    for (int k = 0; k < RC_CACHED_FILM_SLOTS; ++k) {
        sums[k] = (float3)(0.0f);
    }
    uint rays = 0;
    uint finite = 0;
    float coverage = INFINITY;
    for (uint s = 0; s < spp; ++s) {
        const FilmSample c = rc_shade_camera_sample(shader, pixel, s);
        const CachedRadiance l = c.light;
        if (!rc_add_camera_sample(&l, sums, &rays, counters, pixel)) {
            continue;
        }
        ++finite;
        if (l.served) {
            coverage = fmin(coverage, l.coverage);
        }
        sums[RC_CACHED_FILM_LAYER] += c.layer;
        sums[RC_CACHED_FILM_GLOSSY] += c.glossy;
        sums[RC_CACHED_FILM_ORDER].x += c.order;
        sums[RC_CACHED_FILM_HITS].x += c.hits;
    }
    atomic_add(&counters[0], rays);
    const float inv = finite > 0 ? 1.0f / (float)finite : 0.0f;
    RC_GLOBAL float4* out = film + RC_CACHED_FILM_SLOTS * (size_t)pixel;
    for (int k = 0; k < RC_CACHED_FILM_SLOTS; ++k) {
        out[k] = (float4)(sums[k] * inv, 0.0f);
    }
    out[RC_CACHED_FILM_COVERAGE] = (float4)(isfinite(coverage) ? coverage : 0.0f, 0.0f, 0.0f, 0.0f);
}
