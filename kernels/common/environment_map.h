// An environment map: radiance from every direction that leaves the scene, read from an image
// (its texels piecewise constant over the image's square), importance-sampled by a piecewise-
// constant 2D distribution over the image (marginal rows, then a column in the row: pbrt-v4
// §A.5's PiecewiseConstant2D; Pharr et al. 4th ed. §12.5.2), its density converted to solid
// angle by the mapping's Jacobian. Two mappings of the image (u across, v down, in [0, 1)):
// - RC_MAP_LATLONG, Mitsuba 3's `envmap`: in the map's frame, phi = atan2(x, -z) = 2 pi u, theta
//   = acos(y) = pi v (the top row looks up +y); the solid angle of du dv is 2 pi^2 sin(theta);
// - RC_MAP_EQUAL_AREA, pbrt-v4's: Clarberg's equal-area octahedral square ("Fast Equal-Area
//   Mapping of the (Hemi)Sphere using SIMD", 2008), the +z hemisphere in the inner diamond; the
//   solid angle of du dv is 4 pi everywhere.
// The distribution lives in the light-triangle cdf from Light.map_distribution: the rows'
// cumulative weights (height entries), then each row's cumulative weights (width each).
#pragma once

#include "common/cdf.h"
#include "common/math.h"
#include "common/scene_data.h"
#include "shared/types.h"

// The map-frame direction of world direction w (the rows map_x, map_y, map_z), unit.
RC_FUNC float3 rc_map_direction(const Light* light, float3 w) {
    const float3 d =
        (float3)(dot(light->map_x.xyz, w), dot(light->map_y.xyz, w), dot(light->map_z.xyz, w));
    return normalize(d);
}

// The world direction of map-frame direction d: the transpose of the rows (an orthonormal frame:
// the host keeps only rotations and reflections).
RC_FUNC float3 rc_world_direction(const Light* light, float3 d) {
    return d.x * light->map_x.xyz + d.y * light->map_y.xyz + d.z * light->map_z.xyz;
}

// Clarberg's mapping, the sphere to the unit square.
RC_FUNC float2 rc_equal_area_sphere_to_square(float3 d) {
    const float x = fabs(d.x);
    const float y = fabs(d.y);
    const float z = fabs(d.z);
    const float r = sqrt(fmax(0.0f, 1.0f - z));
    const float a = fmax(x, y);
    const float b = a > 0.0f ? fmin(x, y) / a : 0.0f;
    float phi = atan(b) * (2.0f / RC_PI);
    if (x < y) {
        phi = 1.0f - phi;
    }
    float v = phi * r;
    float u = r - v;
    if (d.z < 0.0f) {
        const float t = u;
        u = 1.0f - v;
        v = 1.0f - t;
    }
    u = copysign(u, d.x);
    v = copysign(v, d.y);
    return (float2)(0.5f * (u + 1.0f), 0.5f * (v + 1.0f));
}

// Its inverse, the unit square to the sphere.
RC_FUNC float3 rc_equal_area_square_to_sphere(float2 p) {
    const float u = 2.0f * p.x - 1.0f;
    const float v = 2.0f * p.y - 1.0f;
    const float up = fabs(u);
    const float vp = fabs(v);
    const float signed_distance = 1.0f - (up + vp);
    const float r = 1.0f - fabs(signed_distance);
    const float phi = (r == 0.0f ? 1.0f : (vp - up) / r + 1.0f) * (RC_PI / 4.0f);
    const float z = copysign(1.0f - r * r, signed_distance);
    const float cos_phi = copysign(cos(phi), u);
    const float sin_phi = copysign(sin(phi), v);
    const float s = r * sqrt(fmax(0.0f, 2.0f - r * r));
    return (float3)(cos_phi * s, sin_phi * s, z);
}

// The image coordinates of map-frame direction d.
RC_FUNC float2 rc_map_uv(int mapping, float3 d) {
    if (mapping == RC_MAP_EQUAL_AREA) {
        return rc_equal_area_sphere_to_square(d);
    }
    float u = atan2(d.x, -d.z) * RC_INV_TWO_PI;
    u -= floor(u);
    const float v = acos(clamp(d.y, -1.0f, 1.0f)) * RC_INV_PI;
    return (float2)(u, v);
}

RC_FUNC float3 rc_map_uv_direction(int mapping, float2 uv) {
    if (mapping == RC_MAP_EQUAL_AREA) {
        return rc_equal_area_square_to_sphere(uv);
    }
    const float phi = 2.0f * RC_PI * uv.x;
    const float theta = RC_PI * uv.y;
    const float s = sin(theta);
    return (float3)(s * sin(phi), cos(theta), -s * cos(phi));
}

// The solid angle that a unit of image area covers at uv (du dv -> dw).
RC_FUNC float rc_map_jacobian(int mapping, float2 uv) {
    if (mapping == RC_MAP_EQUAL_AREA) {
        return 4.0f * RC_PI;
    }
    return 2.0f * RC_PI * RC_PI * sin(RC_PI * uv.y);
}

// The texel holding uv, clamped into the image.
RC_FUNC int2 rc_map_texel(TextureInfo info, float2 uv) {
    const int x = clamp((int)(uv.x * (float)info.width), 0, info.width - 1);
    const int y = clamp((int)(uv.y * (float)info.height), 0, info.height - 1);
    return (int2)(x, y);
}

// Radiance from world direction w (leaving the scene) of environment light `light`.
RC_FUNC float3 rc_environment_radiance(const SceneData* scene, const Light* light, float3 w) {
    if (light->map < 0) {
        return light->radiance.xyz;
    }
    const TextureInfo info = scene->textures[light->map];
    const int2 t = rc_map_texel(info, rc_map_uv(light->map_mapping, rc_map_direction(light, w)));
    return scene->texels[info.first_texel + t.y * info.width + t.x].xyz;
}

// The solid-angle density with which rc_sample_environment returns world direction w (light
// selection not included).
RC_FUNC float rc_environment_direction_pdf(const SceneData* scene, const Light* light, float3 w) {
    if (light->map < 0) {
        return RC_INV_FOUR_PI;
    }
    const TextureInfo info = scene->textures[light->map];
    const float2 uv = rc_map_uv(light->map_mapping, rc_map_direction(light, w));
    const float jacobian = rc_map_jacobian(light->map_mapping, uv);
    if (!(jacobian > 0.0f)) {
        return 0.0f;
    }
    const int2 t = rc_map_texel(info, uv);
    RC_GLOBAL const float* rows = scene->light_triangle_cdf + light->map_distribution;
    RC_GLOBAL const float* row = rows + info.height + t.y * info.width;
    const float p = rc_cdf_probability(rows, t.y) * rc_cdf_probability(row, t.x);
    return p * (float)(info.width * info.height) / jacobian;
}

// The offset within cell i of cdf (count entries) that u falls at, in [0, 1).
RC_FUNC float rc_cdf_remainder(RC_GLOBAL const float* cdf, int i, float u) {
    const float low = i > 0 ? cdf[i - 1] : 0.0f;
    const float width = cdf[i] - low;
    return width > 0.0f ? clamp((u - low) / width, 0.0f, 0.99999994f) : 0.5f;
}

// A world direction drawn from the map's distribution from (u1, u2), its density in *pdf
// (solid angle, selection not included; 0 where sampling fails) and the radiance from it in
// *radiance (the sampled texel's).
RC_FUNC float3 rc_sample_environment(const SceneData* scene, const Light* light, float u1, float u2,
                                     float* pdf, float3* radiance) {
    if (light->map < 0) {
        *pdf = RC_INV_FOUR_PI;
        *radiance = light->radiance.xyz;
        const float z = 1.0f - 2.0f * u1;
        const float r = sqrt(fmax(0.0f, 1.0f - z * z));
        const float phi = 2.0f * RC_PI * u2;
        return (float3)(r * cos(phi), r * sin(phi), z);
    }
    const TextureInfo info = scene->textures[light->map];
    RC_GLOBAL const float* rows = scene->light_triangle_cdf + light->map_distribution;
    const int y = rc_sample_cdf(rows, info.height, u1);
    RC_GLOBAL const float* row = rows + info.height + y * info.width;
    const int x = rc_sample_cdf(row, info.width, u2);
    const float2 uv = (float2)(((float)x + rc_cdf_remainder(row, x, u2)) / (float)info.width,
                               ((float)y + rc_cdf_remainder(rows, y, u1)) / (float)info.height);
    const float jacobian = rc_map_jacobian(light->map_mapping, uv);
    const float p = rc_cdf_probability(rows, y) * rc_cdf_probability(row, x);
    *pdf = jacobian > 0.0f ? p * (float)(info.width * info.height) / jacobian : 0.0f;
    *radiance = scene->texels[info.first_texel + y * info.width + x].xyz;
    return rc_world_direction(light, rc_map_uv_direction(light->map_mapping, uv));
}
