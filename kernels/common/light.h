// Light sampling for next-event estimation, and the densities multiple importance sampling needs.
// An area light's triangle is chosen in proportion to its area; from a shading point that sees
// the triangle's emitting side (its winding's) under a large solid angle, a direction is drawn
// uniformly in that solid angle (Arvo 1995), otherwise a point uniformly by area, converted to
// solid angle.
#pragma once

#include "common/cdf.h"
#include "common/environment_map.h"
#include "common/math.h"
#include "common/ray_offset.h"
#include "common/scene_data.h"
#include "common/spherical_triangle.h"
#include "common/triangle_geometry.h"
#include "shared/types.h"

// The smallest solid angle (steradians) under which a light triangle is sampled in solid angle
// rather than by area. Measured (docs/lab/path-tracer.md, "The solid-angle sampling threshold"):
// the direct light's error falls as the threshold falls to 1e-3 sr and no further below it, where
// the two densities are nearly equal and sampling by area is cheaper. Tests build their probes
// with -D to compare the two strategies.
#ifndef RC_SOLID_ANGLE_SAMPLING_MIN
#define RC_SOLID_ANGLE_SAMPLING_MIN 1e-3f
#endif

// The strategy for light triangle `triangle` seen from p, a function of the geometry alone so
// that sampling and the density MIS evaluates agree: the triangle's solid angle when directions
// are drawn uniformly in it (p in front of the emitting side, the solid angle at least
// RC_SOLID_ANGLE_SAMPLING_MIN), 0 when points are drawn uniformly by area. *a, *b, *c: the unit
// directions from p to the vertices (the spherical triangle sampling draws in), where it is not 0.
RC_FUNC float rc_light_triangle_solid_angle(RC_GLOBAL const Triangle* triangle, float3 p, float3* a,
                                            float3* b, float3* c) {
    const float3 v0 = triangle->v0.xyz;
    const float3 winding = cross(triangle->v1.xyz - v0, triangle->v2.xyz - v0);
    if (dot(winding, p - v0) <= 0.0f) {
        return 0.0f;  // behind the emitter or in its plane: nothing to sample in solid angle
    }
    *a = normalize(v0 - p);
    *b = normalize(triangle->v1.xyz - p);
    *c = normalize(triangle->v2.xyz - p);
    const float solid_angle = rc_spherical_triangle_solid_angle(*a, *b, *c);
    return solid_angle >= RC_SOLID_ANGLE_SAMPLING_MIN && solid_angle > 0.0f ? solid_angle : 0.0f;
}

// Solid-angle density of a direction to light triangle `triangle` of area light `light` (chosen
// with probability `selection`) when sampled in solid angle: selection x the triangle's share of
// the light's area x 1 / solid angle.
RC_FUNC float rc_solid_angle_light_pdf(const Light* light, float selection,
                                       RC_GLOBAL const Triangle* triangle, float solid_angle) {
    return selection * (rc_triangle_area(triangle) / light->area) / solid_angle;
}

// A sampled light direction from a shading point.
typedef struct LightSample {
    float3 direction;  // unit, from the shading point to the light
    float3 radiance;   // arriving radiance (intensity / distance^2 for point and spot lights,
                       // the irradiance facing the light for a distant light)
    float pdf;         // solid-angle density, light selection included; 1 for delta lights
    float3 target;     // the end of the shadow ray (offset off an area light's surface)
    bool delta;        // a point, spot or distant light (not reachable by BRDF sampling)
    bool infinite;     // the environment or a distant light: the shadow ray has no end
} LightSample;

// Spot light falloff: 1 inside the beam, 0 outside the cutoff, linear in angle between.
RC_FUNC float rc_spot_falloff(const Light* light, float3 from_light) {
    const float cos_angle = dot(from_light, light->axis.xyz);
    if (cos_angle >= light->cos_beam) {
        return 1.0f;
    }
    if (cos_angle <= light->cos_cutoff) {
        return 0.0f;
    }
    const float angle = acos(clamp(cos_angle, -1.0f, 1.0f));
    return (light->cutoff - angle) / (light->cutoff - light->beam);
}

// Samples area light `light` (chosen with probability `selection`) from point p into *s: a
// triangle by area (u1), then a direction in its solid angle or a point by area (u2, u3).
RC_FUNC void rc_sample_area_light(const SceneData* scene, const Light* light, float selection,
                                  float3 p, float u1, float u2, float u3, LightSample* s) {
    const int first = light->first_triangle;
    const int entry =
        first + rc_sample_cdf(scene->light_triangle_cdf + first, light->triangle_count, u1);
    const uint primitive = scene->light_triangles[entry];
    RC_GLOBAL const Triangle* triangle = scene->triangles + scene->triangle_of_primitive[primitive];
    const float3 nl = rc_triangle_normal(triangle);
    float3 a, b, c;
    const float solid_angle = rc_light_triangle_solid_angle(triangle, p, &a, &b, &c);
    if (solid_angle > 0.0f) {
        // Uniform in the spherical triangle (Arvo 1995); the point is where the direction meets
        // the triangle's plane.
        s->direction = rc_sample_spherical_triangle(a, b, c, solid_angle, u2, u3);
        const float cos_light = -dot(nl, s->direction);
        if (cos_light <= 0.0f) {
            return;
        }
        const float3 q = p + (dot(triangle->v0.xyz - p, -nl) / cos_light) * s->direction;
        s->pdf = rc_solid_angle_light_pdf(light, selection, triangle, solid_angle);
        s->radiance = light->radiance.xyz;
        s->target = rc_offset_ray_origin(q, nl, triangle);
        return;
    }
    // Uniform point on the triangle (pbrt-v3 §13.6.5), its area density converted to solid angle.
    const float su = sqrt(u2);
    const float b0 = 1.0f - su;
    const float b1 = u3 * su;
    const float3 q = rc_hit_point(triangle, b1, 1.0f - b0 - b1);
    const float3 to_light = q - p;
    const float distance2 = dot(to_light, to_light);
    if (distance2 <= 0.0f) {
        return;
    }
    s->direction = to_light / sqrt(distance2);
    const float cos_light = -dot(nl, s->direction);
    if (cos_light <= 0.0f) {
        return;  // the back of a one-sided emitter
    }
    s->pdf = selection * distance2 / (light->area * cos_light);
    s->radiance = light->radiance.xyz;
    s->target = rc_offset_ray_origin(q, nl, triangle);
}

// Samples light l (chosen with probability `selection`) from point p.
RC_FUNC LightSample rc_sample_light(const SceneData* scene, int l, float selection, float3 p,
                                    float u1, float u2, float u3) {
    const Light light = scene->lights[l];
    LightSample s;
    s.delta = false;
    s.infinite = false;
    s.pdf = 0.0f;
    s.radiance = (float3)(0.0f);
    s.direction = (float3)(0.0f, 0.0f, 1.0f);
    s.target = p;
    const int kind = light.kind;
    if (kind == RC_LIGHT_AREA) {
        rc_sample_area_light(scene, &light, selection, p, u1, u2, u3, &s);
    } else if (kind == RC_LIGHT_POINT || kind == RC_LIGHT_SPOT) {
        const float3 to_light = light.position.xyz - p;
        const float distance2 = dot(to_light, to_light);
        if (distance2 <= 0.0f) {
            return s;
        }
        s.direction = to_light / sqrt(distance2);
        s.delta = true;
        s.pdf = selection;
        s.radiance = light.radiance.xyz / distance2;
        if (kind == RC_LIGHT_SPOT) {
            s.radiance *= rc_spot_falloff(&light, -s.direction);
        }
        s.target = light.position.xyz;
    } else if (kind == RC_LIGHT_DISTANT) {
        // A delta direction (pbrt-v4 §12.4): irradiance E on a surface facing it, from outside
        // the scene (the shadow ray has no end).
        s.direction = -light.axis.xyz;
        s.delta = true;
        s.infinite = true;
        s.pdf = selection;
        s.radiance = light.radiance.xyz;
    } else {
        // The environment: uniform directions on the sphere, or by its map's distribution.
        float pdf = 0.0f;
        s.direction = rc_sample_environment(scene, &light, u1, u2, &pdf, &s.radiance);
        s.pdf = selection * pdf;
        s.infinite = true;
    }
    return s;
}

// Density with which light sampling would have produced the direction towards point q on the
// triangle of scene primitive `primitive` of area light l (q seen from p, nl the triangle's unit
// normal, either side): the strategy rc_sample_area_light takes for that triangle from p.
RC_FUNC float rc_area_light_pdf(const SceneData* scene, int l, uint primitive, float3 p, float3 q,
                                float3 nl) {
    const float selection = rc_cdf_probability(scene->light_cdf, l);
    RC_GLOBAL const Triangle* triangle = scene->triangles + scene->triangle_of_primitive[primitive];
    float3 a, b, c;
    const float solid_angle = rc_light_triangle_solid_angle(triangle, p, &a, &b, &c);
    if (solid_angle > 0.0f) {
        const Light light = scene->lights[l];
        return rc_solid_angle_light_pdf(&light, selection, triangle, solid_angle);
    }
    const float3 to_light = q - p;
    const float distance2 = dot(to_light, to_light);
    const float cos_light = fabs(dot(nl, to_light)) / sqrt(distance2);
    if (cos_light <= 0.0f) {
        return 0.0f;
    }
    return selection * distance2 / (scene->lights[l].area * cos_light);
}

// Density of light sampling for a direction that leaves the scene (the environment).
RC_FUNC float rc_environment_pdf(const SceneData* scene, float3 w) {
    if (scene->environment < 0) {
        return 0.0f;
    }
    const Light light = scene->lights[scene->environment];
    return rc_cdf_probability(scene->light_cdf, scene->environment) *
           rc_environment_direction_pdf(scene, &light, w);
}

// Radiance arriving along world direction w from the environment (black without one): what a
// ray that leaves the scene in direction w sees.
RC_FUNC float3 rc_environment_light(const SceneData* scene, float3 w) {
    if (scene->environment < 0) {
        return (float3)(0.0f);
    }
    const Light light = scene->lights[scene->environment];
    return rc_environment_radiance(scene, &light, w);
}
