// The scene's buffers as kernel parameters, in the order host/methods/scene_arguments.h passes
// them, and the SceneData they make. For entry kernels (*.cl) only.
#pragma once

#include "common/scene_data.h"

#define RC_SCENE_PARAMETERS                                                                    \
    RC_GLOBAL const TraversalNode *nodes, RC_GLOBAL const Triangle *triangles,                 \
        RC_GLOBAL const uint *triangle_of_primitive, RC_GLOBAL const TriangleShading *shading, \
        RC_GLOBAL const float4 *normals, RC_GLOBAL const float2 *uvs,                          \
        RC_GLOBAL const Material *materials, RC_GLOBAL const TextureInfo *textures,            \
        RC_GLOBAL const float4 *texels, RC_GLOBAL const Light *lights,                         \
        RC_GLOBAL const float *light_cdf, RC_GLOBAL const uint *light_triangles,               \
        RC_GLOBAL const float *light_triangle_cdf, int light_count, int environment

RC_FUNC SceneData
rc_scene_data(RC_GLOBAL const TraversalNode* nodes, RC_GLOBAL const Triangle* triangles,
              RC_GLOBAL const uint* triangle_of_primitive, RC_GLOBAL const TriangleShading* shading,
              RC_GLOBAL const float4* normals, RC_GLOBAL const float2* uvs,
              RC_GLOBAL const Material* materials, RC_GLOBAL const TextureInfo* textures,
              RC_GLOBAL const float4* texels, RC_GLOBAL const Light* lights,
              RC_GLOBAL const float* light_cdf, RC_GLOBAL const uint* light_triangles,
              RC_GLOBAL const float* light_triangle_cdf, int light_count, int environment) {
    SceneData scene;
    scene.nodes = nodes;
    scene.triangles = triangles;
    scene.triangle_of_primitive = triangle_of_primitive;
    scene.shading = shading;
    scene.normals = normals;
    scene.uvs = uvs;
    scene.materials = materials;
    scene.textures = textures;
    scene.texels = texels;
    scene.lights = lights;
    scene.light_cdf = light_cdf;
    scene.light_triangles = light_triangles;
    scene.light_triangle_cdf = light_triangle_cdf;
    scene.light_count = light_count;
    scene.environment = environment;
    return scene;
}

#define RC_SCENE_DATA()                                                                      \
    rc_scene_data(nodes, triangles, triangle_of_primitive, shading, normals, uvs, materials, \
                  textures, texels, lights, light_cdf, light_triangles, light_triangle_cdf,  \
                  light_count, environment)
