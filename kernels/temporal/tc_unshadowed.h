// The unshadowed irradiance a frame's emitters give a surface point: how temporal caching
// estimates the change of the light a record's hemisphere sees between two frames (the report's
// §4.3: "accounting for the rotation and displacement of both objects and light sources").
#pragma once

#include "common/light.h"
#include "common/math.h"
#include "shared/temporal.h"

// Irradiance at p (normal n) from a uniformly emitting triangle v0 v1 v2 of radiance 1, emitting
// on its winding's side, with no occluder: Lambert's polygon formula, E = n . Phi, Phi = 1/2
// sum_i Theta_i gamma_i over the edges (v_i, v_i+1), Theta_i the angle the edge subtends at p and
// gamma_i the unit normal of the plane through p and the edge, oriented towards the polygon
// (Arvo 1995, "Applications of Irradiance Tensors", eq. 2 and §3). 0 behind the emitting side;
// not clipped to the horizon (a triangle straddling p's tangent plane gives n . Phi, the
// clipped irradiance's first-order estimate, floored at 0).
RC_FUNC float rc_tc_triangle_irradiance(float3 v0, float3 v1, float3 v2, float3 p, float3 n) {
    const float3 winding = cross(v1 - v0, v2 - v0);
    if (dot(winding, p - v0) <= 0.0f) {
        return 0.0f;
    }
    const float3 a = normalize(v0 - p);
    const float3 b = normalize(v1 - p);
    const float3 c = normalize(v2 - p);
    const float3 corners[3] = {a, b, c};
    float3 phi = (float3)(0.0f);
    for (int i = 0; i < 3; ++i) {
        const float3 u = corners[i];
        const float3 w = corners[(i + 1) % 3];
        const float3 normal = cross(u, w);
        const float length_normal = length(normal);
        if (length_normal > 0.0f) {
            const float theta = acos(clamp(dot(u, w), -1.0f, 1.0f));
            phi += (0.5f * theta / length_normal) * normal;
        }
    }
    // Oriented towards the triangle whatever the order its corners appear in from p.
    if (dot(phi, a + b + c) < 0.0f) {
        phi = -phi;
    }
    return fmax(0.0f, dot(n, phi));
}

// Irradiance (rgb) at p with normal n from emitter e, unshadowed.
RC_FUNC float3 rc_tc_emitter_irradiance(RC_GLOBAL const TcEmitter* e, float3 p, float3 n) {
    const Light light = e->light;
    if (light.kind == RC_LIGHT_AREA) {
        return rc_tc_triangle_irradiance(e->v0.xyz, e->v1.xyz, e->v2.xyz, p, n) *
               light.radiance.xyz;
    }
    if (light.kind == RC_LIGHT_CONSTANT) {
        return RC_PI * light.radiance.xyz;  // the whole upper hemisphere
    }
    if (light.kind == RC_LIGHT_DISTANT) {
        return fmax(0.0f, -dot(n, light.axis.xyz)) * light.radiance.xyz;  // E cos(theta)
    }
    const float3 to_light = light.position.xyz - p;
    const float distance2 = dot(to_light, to_light);
    if (distance2 <= 0.0f) {
        return (float3)(0.0f);
    }
    const float3 direction = to_light / sqrt(distance2);
    float falloff = 1.0f;
    if (light.kind == RC_LIGHT_SPOT) {
        falloff = rc_spot_falloff(&light, -direction);
    }
    return (falloff * fmax(0.0f, dot(n, direction)) / distance2) * light.radiance.xyz;
}

// Irradiance (rgb) at p with normal n from every emitter of a frame, unshadowed.
RC_FUNC float3 rc_tc_unshadowed_irradiance(RC_GLOBAL const TcEmitter* emitters, int count, float3 p,
                                           float3 n) {
    float3 sum = (float3)(0.0f);
    for (int i = 0; i < count; ++i) {
        sum += rc_tc_emitter_irradiance(emitters + i, p, n);
    }
    return sum;
}

// The constant environment's radiance (rgb) among a frame's emitters (black without one).
RC_FUNC float3 rc_tc_environment(RC_GLOBAL const TcEmitter* emitters, int count) {
    float3 sum = (float3)(0.0f);
    for (int i = 0; i < count; ++i) {
        if (emitters[i].light.kind == RC_LIGHT_CONSTANT) {
            sum += emitters[i].light.radiance.xyz;
        }
    }
    return sum;
}

// Radiance l leaving a diffusely reflecting point (reflectance rho) carried from a frame whose
// emitters give it unshadowed irradiance e0 to one that gives e1, per channel: scaled by e1 / e0
// where e0 > 0 (the light it reflects is assumed to change as its direct light does), else
// l + rho / pi e1 (it was unlit and is assumed to see the new light unoccluded).
RC_FUNC float3 rc_tc_carry_radiance(float3 l, float3 rho, float3 e0, float3 e1) {
    const float3 added = l + (rho / RC_PI) * e1;
    return (float3)(e0.x > 0.0f ? l.x * (e1.x / e0.x) : added.x,
                    e0.y > 0.0f ? l.y * (e1.y / e0.y) : added.y,
                    e0.z > 0.0f ? l.z * (e1.z / e0.z) : added.z);
}
