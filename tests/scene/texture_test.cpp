// Image textures: sRGB decoding on load, and the device's bilinear lookup with repeat wrapping
// against a host computation.
#include "scene/texture.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <glm/vec2.hpp>

#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

// Writes a width x height RGB image of the given 8-bit values (sRGB-encoded).
void write_png(const std::filesystem::path& path, int width, int height,
               const std::vector<unsigned char>& rgb) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(path.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, rgb.data()));
    out->close();
}

double srgb_to_linear(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

TEST(Texture, EightBitImagesAreDecodedFromSrgb) {
    const auto dir = test::scratch_dir("texture_srgb");
    write_png(dir / "t.png", 2, 1, {0, 128, 255, 64, 200, 10});
    const Texture texture = load_texture(dir / "t.png");
    ASSERT_EQ(texture.width, 2);
    ASSERT_EQ(texture.height, 1);
    EXPECT_NEAR(texture.texels[0].g, srgb_to_linear(128.0 / 255.0), 1e-6);
    EXPECT_NEAR(texture.texels[0].b, 1.0, 1e-6);
    EXPECT_NEAR(texture.texels[1].r, srgb_to_linear(64.0 / 255.0), 1e-6);
    EXPECT_NEAR(texture.max_value, 1.0, 1e-6);
    EXPECT_THROW(load_texture(dir / "missing.png"), Error);
}

// Bilinear interpolation between texel centres, uv (0, 0) at the bottom-left, repeating.
glm::vec3 host_lookup(const Texture& t, glm::vec2 uv) {
    const double x = (uv.x - std::floor(uv.x)) * t.width - 0.5;
    const double y = (1.0 - (uv.y - std::floor(uv.y))) * t.height - 0.5;
    const double x0 = std::floor(x);
    const double y0 = std::floor(y);
    const auto texel = [&](double xi, double yi) {
        int ix = static_cast<int>(xi) % t.width;
        int iy = static_cast<int>(yi) % t.height;
        ix += ix < 0 ? t.width : 0;
        iy += iy < 0 ? t.height : 0;
        return glm::dvec3(t.texels[static_cast<size_t>(iy) * t.width + ix]);
    };
    const double fx = x - x0;
    const double fy = y - y0;
    const glm::dvec3 v = (1 - fy) * ((1 - fx) * texel(x0, y0) + fx * texel(x0 + 1, y0)) +
                         fy * ((1 - fx) * texel(x0, y0 + 1) + fx * texel(x0 + 1, y0 + 1));
    return glm::vec3(v);
}

TEST(Texture, DeviceBilinearLookupMatchesTheHost) {
    const auto dir = test::scratch_dir("texture_lookup");
    std::vector<unsigned char> rgb;
    for (int i = 0; i < 5 * 3 * 3; ++i) {
        rgb.push_back(static_cast<unsigned char>((i * 37) % 256));
    }
    write_png(dir / "t.png", 5, 3, rgb);
    const Texture texture = load_texture(dir / "t.png");
    std::vector<shared::float4> texels;
    for (const glm::vec4& t : texture.texels) {
        texels.push_back({t.r, t.g, t.b, t.a});
    }
    std::vector<glm::vec2> uvs;
    for (int i = 0; i < 400; ++i) {
        // Inside, on texel centres and edges, and wrapping beyond [0, 1].
        uvs.emplace_back(-1.3f + 0.0091f * i, 2.2f - 0.0117f * i);
    }
    uvs.emplace_back(0.1f, 1.0f - 1.0f / 6.0f);  // a texel centre: exact
    Context& context = test::shared_context();
    const Buffer<shared::float4> texel_buffer(context, texels, "texels");
    const Buffer<glm::vec2> uv_buffer(context, uvs, "uvs");
    Buffer<shared::float4> out(context, uvs.size(), "lookups");
    Kernel kernel = context.kernel("texture_probe.cl", "texture_lookup_probe");
    shared::TextureInfo info{};
    info.width = texture.width;
    info.height = texture.height;
    context.launch(kernel, uvs.size(), info, texel_buffer, uv_buffer, out);
    const std::vector<shared::float4> device = out.download();
    for (size_t i = 0; i < uvs.size(); ++i) {
        const glm::vec3 expected = host_lookup(texture, uvs[i]);
        EXPECT_NEAR(device[i].x, expected.x, 1e-5f) << "uv " << uvs[i].x << ", " << uvs[i].y;
        EXPECT_NEAR(device[i].y, expected.y, 1e-5f);
        EXPECT_NEAR(device[i].z, expected.z, 1e-5f);
    }
    EXPECT_NEAR(device.back().x, texture.texels[0].r, 1e-6f);
}

}  // namespace
}  // namespace rc
