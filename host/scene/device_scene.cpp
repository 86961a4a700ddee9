#include "scene/device_scene.h"

#include "device/context.h"
#include "device/memory_need.h"

namespace rc {
namespace {

std::vector<shared::float4> normals_of(const Scene& scene) {
    std::vector<shared::float4> normals;
    normals.reserve(scene.normals.size());
    for (const glm::vec3& n : scene.normals) {
        normals.push_back({n.x, n.y, n.z, 0.0f});
    }
    return normals;
}

std::vector<shared::Material> materials_of(const Scene& scene) {
    std::vector<shared::Material> materials;
    for (const Material& m : scene.materials) {
        materials.push_back(to_device(m));
    }
    return materials;
}

std::vector<shared::TextureInfo> texture_infos_of(const Scene& scene) {
    std::vector<shared::TextureInfo> infos;
    int first = 0;
    for (const Texture& t : scene.textures) {
        shared::TextureInfo info{};
        info.first_texel = first;
        info.width = t.width;
        info.height = t.height;
        infos.push_back(info);
        first += t.width * t.height;
    }
    return infos;
}

std::vector<shared::float4> texels_of(const Scene& scene) {
    std::vector<shared::float4> texels;
    for (const Texture& t : scene.textures) {
        for (const glm::vec4& texel : t.texels) {
            texels.push_back({texel.r, texel.g, texel.b, texel.a});
        }
    }
    return texels;
}

}  // namespace

DeviceScene::DeviceScene(Context& context, const Scene& scene)
    : shading(context, scene.shading, "triangle_shading"),
      normals(context, normals_of(scene), "vertex_normals"),
      uvs(context, scene.uvs, "vertex_uvs"),
      materials(context, materials_of(scene), "materials"),
      textures(context, texture_infos_of(scene), "texture_infos"),
      texels(context, texels_of(scene), "texels"),
      lights(context, scene.lights.lights, "lights"),
      light_cdf(context, scene.lights.cdf, "light_cdf"),
      light_triangles(context, scene.lights.triangles, "light_triangles"),
      light_triangle_cdf(context, scene.lights.triangle_cdf, "light_triangle_cdf"),
      light_count(static_cast<int>(scene.lights.lights.size())),
      environment(scene.lights.environment) {}

size_t DeviceScene::bytes() const {
    return shading.bytes() + normals.bytes() + uvs.bytes() + materials.bytes() + textures.bytes() +
           texels.bytes() + lights.bytes() + light_cdf.bytes() + light_triangles.bytes() +
           light_triangle_cdf.bytes();
}

}  // namespace rc

namespace rc {

uint64_t DeviceScene::bytes_for(const Scene& scene) {
    size_t texels = 0;
    for (const Texture& t : scene.textures) {
        texels += t.texels.size();
    }
    return buffer_bytes(scene.shading.size(), sizeof(shared::TriangleShading)) +
           buffer_bytes(scene.normals.size(), sizeof(shared::float4)) +
           buffer_bytes(scene.uvs.size(), sizeof(glm::vec2)) +
           buffer_bytes(scene.materials.size(), sizeof(shared::Material)) +
           buffer_bytes(scene.textures.size(), sizeof(shared::TextureInfo)) +
           buffer_bytes(texels, sizeof(shared::float4)) +
           buffer_bytes(scene.lights.lights.size(), sizeof(shared::Light)) +
           buffer_bytes(scene.lights.cdf.size(), sizeof(float)) +
           buffer_bytes(scene.lights.triangles.size(), sizeof(unsigned)) +
           buffer_bytes(scene.lights.triangle_cdf.size(), sizeof(float));
}

}  // namespace rc
