// Film layouts: the float4 slots a render pass writes per pixel (pixel p's slot k at
// film[p * SLOTS + k]), read back by host/image/film.h. Declared once here for the kernels and the
// host.
#pragma once

// The path tracer (kernels/path_tracer/path_tracer.cl): sums over the passes. The beauty slot's
// w counts the pixel's finite samples; the other slots' w is 0.
#define RC_PT_FILM_BEAUTY 0
#define RC_PT_FILM_BEAUTY_SQUARED 1  // per-channel sums of squares (the stddev layer)
#define RC_PT_FILM_DIRECT 2
#define RC_PT_FILM_INDIRECT 3
#define RC_PT_FILM_ALBEDO 4
#define RC_PT_FILM_NORMAL 5
#define RC_PT_FILM_SLOTS 6

// The caching methods' render passes (kernels/common/camera_film.h: ic_shade, ivg_shade): the
// means over the pixel's finite camera samples, w 0.
#define RC_CACHED_FILM_BEAUTY 0
#define RC_CACHED_FILM_DIRECT 1
#define RC_CACHED_FILM_INDIRECT 2
#define RC_CACHED_FILM_ALBEDO 3
#define RC_CACHED_FILM_NORMAL 4
// x: the smallest coverage (CachedRadiance.coverage) over the samples the cache serves; 0 when
// one of them is uncovered or none is served.
#define RC_CACHED_FILM_COVERAGE 5
// The method's own layer (irradiance caching: the records overlay; the grid: its diffuse light).
#define RC_CACHED_FILM_LAYER 6
// The glossy lobes' indirect light (radiance caching's glossy-indirect layer).
#define RC_CACHED_FILM_GLOSSY 7
// x: the mean over the samples of the spherical-harmonic order their glossy light used (0: Monte
// Carlo or no glossy lobe; radiance caching's rc-order layer).
#define RC_CACHED_FILM_ORDER 8
// x: the mean over the samples of the fraction of their glossy directions answered from a cache
// without a ray (SDRC's sdrc-hits layer; 0 elsewhere).
#define RC_CACHED_FILM_HITS 9
#define RC_CACHED_FILM_SLOTS 10
