// The scene as the rendering kernels see it: the buffers of host/scene/device_scene.h, and the
// shading point a closest hit describes.
#pragma once

#include "common/diffuse_bounce.h"
#include "common/material.h"
#include "common/math.h"
#include "common/texture.h"
#include "common/traversal_node.h"
#include "common/triangle_geometry.h"
#include "shared/types.h"

typedef struct SceneData {
    RC_GLOBAL const TraversalNode* nodes;
    RC_GLOBAL const Triangle* triangles;
    RC_GLOBAL const uint* triangle_of_primitive;
    RC_GLOBAL const TriangleShading* shading;
    RC_GLOBAL const float4* normals;
    RC_GLOBAL const float2* uvs;
    RC_GLOBAL const Material* materials;
    RC_GLOBAL const TextureInfo* textures;
    RC_GLOBAL const float4* texels;
    RC_GLOBAL const Light* lights;
    RC_GLOBAL const float* light_cdf;           // cumulative selection probability per light
    RC_GLOBAL const uint* light_triangles;      // primitives of the area lights
    RC_GLOBAL const float* light_triangle_cdf;  // cumulative area within each area light
    int light_count;
    int environment;  // index of the constant environment light, or -1
} SceneData;

// A surface point hit by a ray, oriented towards the side the ray came from.
typedef struct SurfacePoint {
    float3 position;
    float3 origin;            // where rays leaving the surface (on the normal's side) start
    float3 through_origin;    // where rays passing through it (to the other side) start
    float3 geometric_normal;  // unit, facing the incoming ray
    Frame shading;            // shading frame; n faces the incoming ray's side
    float2 uv;
    int material;
    int light;   // area light index, or -1
    bool front;  // the ray arrived on the side the geometric normal (winding) points to
} SurfacePoint;

RC_FUNC SurfacePoint rc_surface_point(const SceneData* scene, Ray ray, Hit hit) {
    SurfacePoint sp;
    RC_GLOBAL const Triangle* triangle =
        scene->triangles + scene->triangle_of_primitive[hit.primitive];
    const TriangleShading shading = scene->shading[hit.primitive];
    sp.position = rc_hit_point(triangle, hit.u, hit.v);
    float3 ng = rc_triangle_normal(triangle);
    const float w = 1.0f - hit.u - hit.v;
    float3 ns = ng;
    if (shading.normal0 >= 0) {
        ns = normalize(w * scene->normals[shading.normal0].xyz +
                       hit.u * scene->normals[shading.normal1].xyz +
                       hit.v * scene->normals[shading.normal2].xyz);
        if (dot(ns, ng) < 0.0f) {
            ns = -ns;  // vertex normals on the other side than the winding
        }
    }
    sp.front = dot(ng, ray.direction.xyz) < 0.0f;
    if (!sp.front) {
        ng = -ng;
        ns = -ns;
    }
    sp.geometric_normal = ng;
    sp.origin = rc_offset_surface_origin(sp.position, ng, triangle);
    sp.through_origin = rc_offset_surface_origin(sp.position, -ng, triangle);
    sp.uv = (float2)(0.0f, 0.0f);
    float3 tangent = (float3)(0.0f);
    if (shading.uv0 >= 0) {
        const float2 t0 = scene->uvs[shading.uv0];
        const float2 t1 = scene->uvs[shading.uv1];
        const float2 t2 = scene->uvs[shading.uv2];
        sp.uv = w * t0 + hit.u * t1 + hit.v * t2;
        // dp/du from the triangle's texture mapping orients anisotropic lobes.
        const float2 d1 = t1 - t0;
        const float2 d2 = t2 - t0;
        const float det = d1.x * d2.y - d1.y * d2.x;
        if (det != 0.0f) {
            const float3 e1 = triangle->v1.xyz - triangle->v0.xyz;
            const float3 e2 = triangle->v2.xyz - triangle->v0.xyz;
            tangent = (d2.y * e1 - d1.y * e2) / det;
        }
    }
    tangent -= ns * dot(ns, tangent);
    const float length_t = length(tangent);
    sp.shading.n = ns;
    if (length_t > 1e-12f) {
        sp.shading.t = tangent / length_t;
        sp.shading.b = cross(ns, sp.shading.t);
    } else {
        rc_orthonormal_basis(ns, &sp.shading.t, &sp.shading.b);
    }
    sp.material = shading.material;
    sp.light = shading.light;
    return sp;
}

// The material at a surface point, its diffuse texture applied; a dielectric's index seen from
// the side the ray arrived on (the material's index inside, where the winding's normal points
// away from, over 1 outside).
RC_FUNC SurfaceMaterial rc_surface_material(const SceneData* scene, const SurfacePoint* sp) {
    const Material material = scene->materials[sp->material];
    SurfaceMaterial m = rc_surface_material_of(&material);
    if (material.texture >= 0) {
        const float3 texel =
            rc_texture_lookup(scene->texels, scene->textures[material.texture], sp->uv);
        if (material.model != RC_MATERIAL_DIFFUSE_TRANSMISSION) {
            m.diffuse *= texel;
        }
        if ((material.texture_targets & RC_TEXTURE_SCALES_REFLECTANCE) != 0) {
            m.specular *= texel;  // a diffuse transmitter's reflectance
        }
        if ((material.texture_targets & RC_TEXTURE_SCALES_TRANSMITTANCE) != 0) {
            m.k *= texel;  // its transmittance
        }
    }
    if (material.model == RC_MATERIAL_DIELECTRIC && !sp->front) {
        m.eta.x = 1.0f / m.eta.x;
    }
    return m;
}
