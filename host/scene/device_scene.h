// A scene's shading data uploaded for the rendering kernels (kernels/common/scene_data.h): per-
// triangle shading, vertex normals and uvs, materials, textures and lights. The geometry itself
// is in the DeviceBvh.
#pragma once

#include <glm/vec2.hpp>

#include "device/buffer.h"
#include "scene/scene.h"
#include "shared/types.h"

namespace rc {

class Context;

struct DeviceScene {
    DeviceScene(Context& context, const Scene& scene);

    Buffer<shared::TriangleShading> shading;
    Buffer<shared::float4> normals;
    Buffer<glm::vec2> uvs;
    Buffer<shared::Material> materials;
    Buffer<shared::TextureInfo> textures;
    Buffer<shared::float4> texels;
    Buffer<shared::Light> lights;
    Buffer<float> light_cdf;
    Buffer<unsigned> light_triangles;
    Buffer<float> light_triangle_cdf;
    int light_count = 0;
    int environment = -1;

    size_t bytes() const;
    // What the constructor allocates for `scene`, before it does.
    static uint64_t bytes_for(const Scene& scene);
};

}  // namespace rc
