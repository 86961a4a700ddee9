// pbrt-v4 import (scene/pbrt_loader.h) and `radcache convert` of it: the Cornell box in pbrt's
// format (tools/make_pbrt_test_scenes.py) renders the image of scenes/cornell-box bitwise; an
// asymmetric scene lands where pbrt puts it (pbrt's camera space is left-handed: no mirroring),
// with its transforms, materials, lights and instances as docs/scene-format.md says; PLY meshes
// load in ASCII and binary; refused and malformed inputs give one line naming file:line.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <tuple>

#include "cli_render.h"
#include "fuzz_targets.h"
#include "glossy_scenes.h"  // test::bitwise_equal
#include "image/image_io.h"
#include "scene/pbrt_loader.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::filesystem::path data(const std::string& name) {
    return test::source_dir() / "tests/data/pbrt" / name;
}

// test::render_scene_file with `options` (by default, at 32 x 32).
Image render(const std::filesystem::path& scene, const std::filesystem::path& out,
             const std::vector<std::string>& options = {"--width", "32", "--height", "32"}) {
    return test::render_scene_file(scene, out, options);
}

TEST(Pbrt, CornellBoxRendersTheJsonScenesImageBitwise) {
    const auto dir = test::scratch_dir("pbrt_cornell");
    const Image json = render(test::source_dir() / "scenes/cornell-box/scene.json", dir / "j.exr");
    const Image pbrt = render(data("cornell-box.pbrt"), dir / "p.exr");
    EXPECT_TRUE(test::bitwise_equal(json, pbrt));
    // The scene's own settings came across: 64 samples, depth 64, 512 x 512.
    const Scene scene = load_scene(data("cornell-box.pbrt"));
    EXPECT_EQ(scene.render.spp, 64);
    EXPECT_EQ(scene.render.max_depth, 64);
    EXPECT_EQ(scene.base_camera.width, 512);
    EXPECT_EQ(scene.base_camera.filter.type, RC_FILTER_BOX);
}

void expect_near(glm::vec3 a, glm::vec3 b, const std::string& what) {
    EXPECT_LT(glm::length(a - b), 1e-5f)
        << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") against (" << b.x << ", " << b.y
        << ", " << b.z << ")";
}

glm::vec3 world(const Shape& shape, glm::vec3 p) {
    return glm::vec3(shape.transform * glm::vec4(p, 1.0f));
}

// Values worked out by hand from tools/make_pbrt_test_scenes.py's hierarchy(). The camera looks
// from the origin along +z with pbrt's plain LookAt, so the import mirrors pbrt's world about the
// plane x = 0 (pbrt_loader.h): a pbrt point (x, y, z) is (-x, y, z) in radcache's world.
TEST(Pbrt, HierarchyTransformsMaterialsLightsAndInstances) {
    const Scene scene = load_scene(data("hierarchy.pbrt"));
    ASSERT_EQ(scene.shapes.size(), 5u);
    // The lamp: object (x, y, 0) -> pbrt (2 - 0.25 y, 0.5 x, 4), ReverseOrientation.
    const Shape& lamp = scene.shapes[0];
    for (const glm::vec3& p : lamp.mesh.positions) {
        expect_near(world(lamp, p), glm::vec3(-(2.0f - 0.25f * p.y), 0.5f * p.x, 4.0f), "lamp");
    }
    EXPECT_TRUE(lamp.flip_normals);
    ASSERT_EQ(lamp.emission.size(), 1u);
    expect_near(lamp.emission[0], glm::vec3(1.0f), "lamp radiance");
    EXPECT_EQ(scene.materials[lamp.materials[0]].name, "default");
    // The plate: ConcatTransform scale 2, translate (-2, 0, 6); a conductor.
    const Shape& plate = scene.shapes[1];
    expect_near(world(plate, {-1, -1, 0}), glm::vec3(4, -2, 6), "plate");
    const Material& gold = scene.materials[plate.materials[0]];
    EXPECT_EQ(gold.kind, MaterialKind::kConductor);
    expect_near(gold.diffuse, glm::vec3(0.0f), "conductor diffuse");
    expect_near(gold.eta, glm::vec3(0.2f, 0.4f, 1.4f), "conductor eta");
    EXPECT_NEAR(gold.k.r, 3.5f, 1e-6f);
    EXPECT_NEAR(gold.alpha_x, 0.09f, 1e-6f);  // roughness 0.09, not remapped
    EXPECT_NEAR(gold.alpha_y, 0.09f, 1e-6f);
    // The picture: Transform replaces the CTM; an image texture times 0.5, uvs as given.
    const Shape& picture = scene.shapes[2];
    expect_near(world(picture, {1, 1, 0}), glm::vec3(-1, 0.5, 8), "picture");
    const Material& checks = scene.materials[picture.materials[0]];
    EXPECT_EQ(checks.kind, MaterialKind::kDiffuse);
    ASSERT_GE(checks.diffuse_texture, 0);
    EXPECT_EQ(scene.textures[checks.diffuse_texture].width, 2);
    expect_near(checks.diffuse, glm::vec3(0.5f), "texture scale");
    ASSERT_EQ(picture.mesh.uvs.size(), 4u);
    EXPECT_EQ(picture.mesh.uvs[2], glm::vec2(1.0f, 1.0f));
    // Two instances of the tile: scale 0.25 inside the object, translate (0, +-1, 5) outside;
    // coateddiffuse: Fresnel 0.04 at eta 1.5, the base times 0.96, roughness 0: a near mirror.
    expect_near(world(scene.shapes[3], {1, 1, 0}), glm::vec3(-0.25f, 1.25f, 5.0f), "tile 1");
    expect_near(world(scene.shapes[4], {1, 1, 0}), glm::vec3(-0.25f, -0.75f, 5.0f), "tile 2");
    const Material& tile = scene.materials[scene.shapes[3].materials[0]];
    EXPECT_EQ(tile.kind, MaterialKind::kPhong);
    expect_near(tile.specular, glm::vec3(0.04f), "coat F0");
    expect_near(tile.diffuse, 0.96f * glm::vec3(0.2f, 0.6f, 0.2f), "coat base");
    EXPECT_FLOAT_EQ(tile.exponent, 1e6f);
    EXPECT_EQ(scene.shapes[4].materials[0], scene.shapes[3].materials[0]);
    // The named "coat" no shape uses is not made: default, gold, checks, tile.
    EXPECT_EQ(scene.materials.size(), 4u);
    // The Include's lights: a point at pbrt (1, 2, 3) + from (1, 0, 0); a spot from (0, 4, 5)
    // down to (0, 3, 5), I 20 x scale 0.5, cone 30 degrees, full beam 30 - 10.
    ASSERT_EQ(scene.emitters.size(), 2u);
    EXPECT_EQ(scene.emitters[0].kind, EmitterKind::kPoint);
    expect_near(scene.emitters[0].position, glm::vec3(-2, 2, 3), "point light");
    expect_near(scene.emitters[0].intensity, glm::vec3(5, 4, 3), "point intensity");
    EXPECT_EQ(scene.emitters[1].kind, EmitterKind::kSpot);
    expect_near(scene.emitters[1].position, glm::vec3(0, 4, 5), "spot");
    expect_near(scene.emitters[1].look_at, glm::vec3(0, 3, 5), "spot target");
    expect_near(scene.emitters[1].intensity, glm::vec3(10), "spot intensity");
    EXPECT_FLOAT_EQ(scene.emitters[1].cutoff_angle, 30.0f);
    EXPECT_FLOAT_EQ(scene.emitters[1].beam_width, 20.0f);
    // Camera, film, sampler, integrator, filter.
    expect_near(scene.base_camera.position, glm::vec3(0), "camera");
    expect_near(scene.base_camera.look_at, glm::vec3(0, 0, 1), "camera look_at");
    expect_near(scene.base_camera.up, glm::vec3(0, 1, 0), "camera up");
    EXPECT_EQ(scene.base_camera.fov_axis, FovAxis::kSmaller);
    EXPECT_FLOAT_EQ(scene.base_camera.fov_degrees, 90.0f);
    EXPECT_EQ(scene.base_camera.width, 64);
    EXPECT_EQ(scene.base_camera.height, 32);
    EXPECT_EQ(scene.base_camera.sampler, RC_SAMPLER_INDEPENDENT);
    EXPECT_EQ(scene.render.spp, 4);
    EXPECT_EQ(scene.render.max_depth, 3);
}

// pbrt's image has world +x on the right (its camera x is cross(up, forward)): the lamp, at pbrt
// x in [1.75, 2.25], y in [-0.5, 0.5], z = 4, covers exactly pixels x 39-40, y 14-17 of the
// 64 x 32 image (fov 90 on the vertical: raster x = (x / z + 2) * 16, y = (1 - y / z) * 16).
TEST(Pbrt, ImageIsNotMirroredAndLandsWhereHandWorked) {
    const auto dir = test::scratch_dir("pbrt_mirror");
    const Image image = render(data("hierarchy.pbrt"), dir / "h.exr", {"-D", "max_depth=0"});
    ASSERT_EQ(image.width, 64);
    ASSERT_EQ(image.height, 32);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const bool lamp = x >= 39 && x <= 40 && y >= 14 && y <= 17;
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(image.at(x, y, c), lamp ? 1.0f : 0.0f, 1e-6f)
                    << "pixel (" << x << ", " << y << ")";
            }
        }
    }
}

// A wide film: pbrt's fov spans the shorter axis (y here), as the lamp's pixels above show; a tall
// one spans x.
TEST(Pbrt, FovSpansTheShorterAxis) {
    const auto dir = test::scratch_dir("pbrt_fov");
    std::string text = read_file(data("hierarchy.pbrt"));
    text.replace(text.find("64 \"integer yresolution\" 32"), 27, "32 \"integer yresolution\" 64");
    text.replace(text.find("Include"), std::string::npos, "");
    write_file_atomically(dir / "tall.pbrt", text);
    write_file_atomically(dir / "checker.png", read_file(data("checker.png")));
    // Tall 32 x 64: fov 90 on x, screen x in [-1, 1], y in [-2, 2]; the lamp's x / z in
    // [0.4375, 0.5625] is raster x = (x / z + 1) * 16 in [23, 25); y / z in [-0.125, 0.125] is
    // raster y = (2 - y / z) * 16 in [30, 34).
    const Image image = render(dir / "tall.pbrt", dir / "t.exr", {"-D", "max_depth=0"});
    ASSERT_EQ(image.width, 32);
    ASSERT_EQ(image.height, 64);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const bool lamp = x >= 23 && x <= 24 && y >= 30 && y <= 33;
            EXPECT_NEAR(image.at(x, y, 0), lamp ? 1.0f : 0.0f, 1e-6f) << x << ", " << y;
        }
    }
}

// A PLY with a triangle and a quad, with normals and uvs, in ASCII and binary little-endian.
std::string ply_header(const std::string& format) {
    return "ply\nformat " + format +
           " 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
           "property float nx\nproperty float ny\nproperty float nz\nproperty float u\n"
           "property float v\nelement face 2\nproperty list uchar int vertex_indices\n"
           "end_header\n";
}

const float kPlyVertices[5][8] = {{0, 0, 0, 0, 0, 1, 0, 0},
                                  {1, 0, 0, 0, 0, 1, 1, 0},
                                  {1, 1, 0, 0, 0, 1, 1, 1},
                                  {0, 1, 0, 0, 0, 1, 0, 1},
                                  {2, 0, 0, 0, 0, 1, 0.5f, 0.5f}};

std::string ascii_ply() {
    std::string text = ply_header("ascii");
    for (const auto& v : kPlyVertices) {
        for (float x : v) {
            text += std::to_string(x) + " ";
        }
        text += "\n";
    }
    return text + "4 0 1 2 3\n3 1 4 2\n";
}

std::string binary_ply() {
    std::string bytes = ply_header("binary_little_endian");
    for (const auto& v : kPlyVertices) {
        bytes.append(reinterpret_cast<const char*>(v), sizeof v);
    }
    for (const std::vector<int32_t>& face : {std::vector<int32_t>{0, 1, 2, 3}, {1, 4, 2}}) {
        bytes += static_cast<char>(face.size());
        bytes.append(reinterpret_cast<const char*>(face.data()), face.size() * 4);
    }
    return bytes;
}

// binary_ply() in big-endian byte order: every 4-byte value reversed, the counts (bytes) kept.
std::string big_endian_ply() {
    std::string bytes = ply_header("binary_big_endian");
    const std::string little = binary_ply().substr(ply_header("binary_little_endian").size());
    size_t at = 0;
    const auto swap_values = [&](size_t count) {
        for (size_t k = 0; k < count; ++k, at += 4) {
            bytes += {little[at + 3], little[at + 2], little[at + 1], little[at]};
        }
    };
    swap_values(5 * 8);
    for (size_t corners : {4, 3}) {
        bytes += little[at++];
        swap_values(corners);
    }
    return bytes;
}

// binary_ply() with a first vertex property "uchar flags" of 10: the body's first byte is 0x0a,
// a line feed (Assimp 5.2 skipped it as the header's line end and read every value shifted).
std::string line_feed_first_ply() {
    std::string header = ply_header("binary_little_endian");
    header.replace(header.find("property float x"), 0, "property uchar flags\n");
    std::string bytes = header;
    for (const auto& v : kPlyVertices) {
        bytes += '\x0a';
        bytes.append(reinterpret_cast<const char*>(v), sizeof v);
    }
    return bytes +
           binary_ply().substr(ply_header("binary_little_endian").size() + sizeof kPlyVertices);
}

// `bytes` gzip-compressed through zlib (as `gzip` writes .ply.gz files).
std::string gzipped(const std::string& bytes) {
    z_stream stream{};
    EXPECT_EQ(deflateInit2(&stream, 6, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY), Z_OK);
    std::string out(deflateBound(&stream, bytes.size()), '\0');
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    stream.avail_in = static_cast<uInt>(bytes.size());
    stream.next_out = reinterpret_cast<Bytef*>(out.data());
    stream.avail_out = static_cast<uInt>(out.size());
    EXPECT_EQ(deflate(&stream, Z_FINISH), Z_STREAM_END);
    out.resize(stream.total_out);
    deflateEnd(&stream);
    return out;
}

std::filesystem::path write_ply_scene(const std::filesystem::path& dir, const std::string& name,
                                      const std::string& ply,
                                      const std::string& extension = ".ply") {
    write_file_atomically(dir / (name + extension), ply);
    const auto scene = dir / (name + ".pbrt");
    write_file_atomically(scene,
                          "LookAt 0.5 0.5 5  0.5 0.5 0  0 1 0\nCamera \"perspective\"\n"
                          "WorldBegin\nAreaLightSource \"diffuse\"\nShape \"plymesh\" "
                          "\"string filename\" \"" +
                              name + extension + "\"\n");
    return scene;
}

// The same mesh in ASCII, binary of both byte orders, binary with a first byte 0x0a and an extra
// property to skip, and gzipped as a .ply.gz: the same triangles, normals and uvs.
TEST(Pbrt, PlyMeshesLoadInAsciiAndBinary) {
    const auto dir = test::scratch_dir("pbrt_ply");
    for (const auto& [name, ply, extension] :
         {std::tuple<std::string, std::string, std::string>{"ascii", ascii_ply(), ".ply"},
          {"binary", binary_ply(), ".ply"},
          {"big_endian", big_endian_ply(), ".ply"},
          {"line_feed_first", line_feed_first_ply(), ".ply"},
          {"gzipped", gzipped(binary_ply()), ".ply.gz"}}) {
        SCOPED_TRACE(name);
        const Scene scene = load_scene(write_ply_scene(dir, name, ply, extension));
        ASSERT_EQ(scene.shapes.size(), 1u);
        const TriangleMesh& mesh = scene.shapes[0].mesh;
        ASSERT_EQ(mesh.triangles.size(), 3u);  // the quad split in two
        ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
        // Every triangle corner is one of the file's vertices, with its normal and uv.
        double area = 0.0;
        for (const glm::uvec3& t : mesh.triangles) {
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 p = mesh.positions[t[k]];
                bool found = false;
                for (const auto& v : kPlyVertices) {
                    if (p == glm::vec3(v[0], v[1], v[2])) {
                        found = true;
                        EXPECT_EQ(mesh.uvs[t[k]], glm::vec2(v[6], v[7]));
                        expect_near(mesh.normals[t[k]], glm::vec3(0, 0, 1), "normal");
                    }
                }
                EXPECT_TRUE(found);
            }
            const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y],
                            c = mesh.positions[t.z];
            area += glm::length(glm::cross(b - a, c - a)) / 2.0;
            EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f);  // the file's winding kept
        }
        EXPECT_NEAR(area, 1.5, 1e-6);  // the unit quad and the triangle (1,0) (2,0) (1,1)
    }
}

// The error of loading the scene of `ply`, or "" when it loads.
std::string ply_error(const std::filesystem::path& dir, const std::string& name,
                      const std::string& ply) {
    try {
        load_scene(write_ply_scene(dir, name, ply));
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

// A list count the file cannot hold (2^30 indices: 4 GiB that a reader would allocate) and a
// file that ends inside an element are refused by the body's walk, naming the element, in both
// formats; the intact files still load.
TEST(Pbrt, PlyListCountsAndTruncationAreBoundedByTheFile) {
    const auto dir = test::scratch_dir("pbrt_ply_bounds");
    std::string binary = binary_ply();
    const std::string wide_header = ply_header("binary_little_endian");
    std::string wide = wide_header;  // list counts as int: room for 2^30
    wide.replace(wide.find("list uchar int"), 14, "list int int");
    wide += binary.substr(wide_header.size(), 5 * sizeof kPlyVertices[0]);
    const int32_t huge = 1 << 30;
    wide.append(reinterpret_cast<const char*>(&huge), 4);
    wide += std::string(40, '\0');
    std::string ascii = ascii_ply();
    struct Case {
        std::string name, ply, expected;
    };
    for (const Case& c : std::vector<Case>{
             {"binary_huge_list", wide, "element face 0: a list of 1073741824 values runs past"},
             {"binary_truncated", binary.substr(0, binary.size() - 5),
              "element face 1: a list of 3 values runs past the end of the file"},
             {"ascii_huge_list", ascii.substr(0, ascii.size() - 8) + "1073741824 1 4 2\n",
              "element face 1: a list count of 1073741824"},
             {"ascii_truncated", ascii.substr(0, ascii.size() - 4) + "\n",
              "element face 1: a list count of 3"}}) {
        const std::string error = ply_error(dir, c.name, c.ply);
        EXPECT_NE(error.find(c.expected), std::string::npos) << c.name << ": " << error;
        EXPECT_NE(error.find(c.name + ".pbrt:5: Shape \"plymesh\""), std::string::npos)
            << c.name << ": " << error;
    }
    EXPECT_EQ(ply_error(dir, "binary", binary), "");
    EXPECT_EQ(ply_error(dir, "ascii", ascii), "");
}

struct Refusal {
    std::string name;
    std::string text;      // after the standard header; the error is on its last line
    std::string expected;  // in the error line
    int line = 0;          // the line the error names; 0: the case's last
    int exit_code = 2;     // 2: a refused feature; 1: a malformed file
};

// The header every refusal case follows: 5 lines, so a case's first line is line 6.
const char* kHeader =
    "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\nFilm \"rgb\"\nWorldBegin\n"
    "LightSource \"point\" \"point3 from\" [0 0 -4]\n";
const char* kTriangle = "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0]\n";

// Runs `radcache render` on the case; expects `exit_code` (1: malformed, 2: a feature radcache
// does not have), one line naming file:line, no image.
void expect_refused(const std::filesystem::path& dir, const std::string& name,
                    const std::string& text, const std::string& expected, int line,
                    int exit_code = 1) {
    const auto file = dir / (name + ".pbrt");
    write_file_atomically(file, text);
    const test::CommandResult result = test::run_radcache(
        {"render", file.string(), "-o", (dir / "out.png").string(), "--spp", "1"});
    EXPECT_EQ(result.exit_code, exit_code) << name << ": " << result.output;
    const std::string where =
        "radcache: error: " + file.string() + (line > 0 ? ":" + std::to_string(line) + ":" : "");
    EXPECT_EQ(result.output.rfind(where, 0), 0u) << name << ": " << result.output;
    EXPECT_NE(result.output.find(expected), std::string::npos) << name << ": " << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1)
        << name << ": " << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png")) << name;
}

TEST(Pbrt, RefusedDirectivesNameFileAndLine) {
    const auto dir = test::scratch_dir("pbrt_refused");
    const std::vector<Refusal> cases = {
        {"curve", "Shape \"curve\" \"point3 P\" [0 0 0 1 0 0 2 0 0 3 0 0]\n",
         "Shape \"curve\" is not supported"},
        {"subsurface", std::string("Material \"subsurface\"\n") + kTriangle,
         "Material \"subsurface\" is not supported", 6},
        {"unknown_glass",
         std::string("Material \"dielectric\" \"spectrum eta\" \"glass-Unobtainium\"\n") +
             kTriangle,
         "\"glass-Unobtainium\" is neither one of pbrt-v4's named spectra nor a file", 6, 1},
        {"goniometric", "LightSource \"goniometric\"\n",
         "LightSource \"goniometric\" is not supported"},
        {"blackbody_reflectance",
         std::string("Material \"diffuse\" \"blackbody reflectance\" [6500]\n") + kTriangle,
         "blackbody spectra are not supported", 6},
        {"twosided", "AreaLightSource \"diffuse\" \"bool twosided\" true\n",
         "two-sided area lights are not supported"},
        {"medium", "MediumInterface \"fog\" \"\"\n", "participating media are not supported"},
        {"envmap_illuminance",
         "LightSource \"infinite\" \"string filename\" \"sky.exr\" \"float illuminance\" 10\n",
         "\"illuminance\" of an image map is not supported"},
        {"marble",
         "Texture \"c\" \"spectrum\" \"marble\"\nMaterial \"diffuse\" \"texture "
         "reflectance\" \"c\"\n" +
             std::string(kTriangle),
         "is of class \"marble\"", 7},
        {"missing_spectrum_file",
         std::string("Material \"conductor\" \"spectrum eta\" \"metal.spd\"\n") + kTriangle,
         "is neither one of pbrt-v4's named spectra nor a file", 6, 1},
        {"unknown", "Frobnicate 1 2 3\n", "unknown directive 'Frobnicate'", 0, 1},
        {"two_skies", "LightSource \"infinite\"\nLightSource \"infinite\"\n",
         "at most one infinite light"},
        {"motion", "ActiveTransform StartTime\n", "animated transforms (motion blur)"},
        {"partial_sphere", "Shape \"sphere\" \"float zmax\" 0.5\n", "partial spheres"},
        {"light_spectrum",
         "LightSource \"point\" \"spectrum I\" [400 1 700 1]\n" + std::string(kTriangle),
         "spectrum spectra are not supported", 6},
        {"alpha", "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"float alpha\" 0.5\n",
         "alpha cut-outs are not supported"},
    };
    for (const Refusal& c : cases) {
        const std::string text = std::string(kHeader) + c.text;
        const int last = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
        expect_refused(dir, c.name, text, c.expected, c.line > 0 ? c.line : last, c.exit_code);
    }
    // Camera and filter types: in the options block.
    expect_refused(dir, "ortho", "Camera \"orthographic\"\nWorldBegin\n",
                   "Camera \"orthographic\" is not supported", 1, 2);
    expect_refused(dir, "mitchell", "PixelFilter \"mitchell\"\nWorldBegin\n",
                   "PixelFilter \"mitchell\" is not supported", 1, 2);
    expect_refused(dir, "shape_first", std::string(kTriangle) + "WorldBegin\n",
                   "Shape is not allowed before WorldBegin", 1);
    // The camera's medium (pbrt-v4 allows media before WorldBegin): refused as unsupported.
    expect_refused(dir, "camera_medium",
                   "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
                   "MediumInterface \"\" \"fog\"\nCamera \"perspective\"\nWorldBegin\n",
                   "participating media are not supported", 2, 2);
    // A token in Latin-1: quoted with its byte escaped, not copied raw into the line.
    expect_refused(dir, "latin1", std::string(kHeader) + "Shape \"tr\xe9s\"\n",
                   "Shape \"tr\\xe9s\" is not supported", 6, 2);
}

// pbrt-v4's photometric normalisations for an RGB illuminant (lights.cpp's Create functions):
// "power" P gives a point light I x scale x P / (4 pi), a spot I x scale x P / k_e with
// k_e = 2 pi ((1 - cos(cone - delta)) + (cos(cone - delta) - cos cone) / 2); "illuminance" E
// gives a distant light irradiance L x scale x E on a surface facing it and the constant
// environment radiance L x scale x E / pi. The distant light travels from "from" to "to" in its
// object space, through the CTM (here a rotation) and pbrt's mirrored x.
// Dielectrics and conductors as pbrt-v4 defines them: "eta" (an index below 1 inverted),
// roughness per axis remapped by sqrt unless "remaproughness" is false, a conductor's
// "reflectance" as eta 1 and k = 2 sqrt(r / (1 - r)).
TEST(Pbrt, DielectricsAndConductorsTakePbrtV4Parameters) {
    const auto dir = test::scratch_dir("pbrt_bsdfs");
    const auto file = dir / "bsdfs.pbrt";
    const std::string triangle = kTriangle;
    write_file_atomically(
        file, std::string(kHeader) + "Material \"dielectric\" \"float eta\" 1.33\n" + triangle +
                  "Material \"dielectric\" \"float eta\" 0.5 \"float roughness\" 0.04\n" +
                  triangle + "Material \"thindielectric\"\n" + triangle +
                  "Material \"conductor\" \"rgb eta\" [0.2 0.9 1.1] \"rgb k\" [3.9 2.4 2.1]\n"
                  "    \"float uroughness\" 0.01 \"float vroughness\" 0.16\n" +
                  triangle + "Material \"conductor\" \"rgb reflectance\" [0.8 0.5 0.2]\n" +
                  triangle +
                  "Material \"diffusetransmission\" \"rgb transmittance\" [0.4 0.5 0.6]\n"
                  "    \"float scale\" 0.5\n" +
                  triangle);
    const Scene scene = load_scene(file);
    ASSERT_EQ(scene.shapes.size(), 6u);
    const auto material = [&](size_t i) { return scene.materials[scene.shapes[i].materials[0]]; };
    EXPECT_EQ(material(5).kind, MaterialKind::kDiffuseTransmission);
    EXPECT_NEAR(material(5).specular.r, 0.125f, 1e-6f);  // the default 0.25 times the scale
    EXPECT_NEAR(material(5).transmittance.b, 0.3f, 1e-6f);
    EXPECT_EQ(material(0).kind, MaterialKind::kDielectric);
    EXPECT_FLOAT_EQ(material(0).ior, 1.33f);
    EXPECT_FLOAT_EQ(material(0).alpha_x, 0.0f);
    EXPECT_FLOAT_EQ(material(1).ior, 2.0f);
    EXPECT_NEAR(material(1).alpha_x, 0.2f, 1e-6f);
    EXPECT_EQ(material(2).kind, MaterialKind::kThinDielectric);
    EXPECT_FLOAT_EQ(material(2).ior, 1.5f);  // pbrt-v4's default
    EXPECT_EQ(material(3).kind, MaterialKind::kConductor);
    EXPECT_NEAR(material(3).alpha_x, 0.1f, 1e-6f);
    EXPECT_NEAR(material(3).alpha_y, 0.4f, 1e-6f);
    EXPECT_NEAR(material(3).k.g, 2.4f, 1e-6f);
    EXPECT_NEAR(material(4).k.r, 2.0f * std::sqrt(0.8f / 0.2f), 1e-5f);
    EXPECT_FLOAT_EQ(material(4).eta.b, 1.0f);
    const auto bad = test::scratch_dir("pbrt_bsdfs_bad");
    expect_refused(bad, "eta_zero",
                   std::string(kHeader) + "Material \"dielectric\" \"float eta\" 0\n" + triangle,
                   "eta must lie in (0, 10]", 6, 1);
    expect_refused(bad, "roughness_negative",
                   std::string(kHeader) +
                       "Material \"conductor\" \"rgb reflectance\" [1 1 1]\n"
                       "    \"float roughness\" -0.1\n" +
                       triangle,
                   "roughness must lie in [0, 1000]", 6, 1);
    expect_refused(bad, "conductor_eta_negative",
                   std::string(kHeader) +
                       "Material \"conductor\" \"rgb eta\" [-1 1 1] \"rgb k\" [1 1 1]\n" + triangle,
                   "eta must lie in (0, 100]", 6, 1);
}

// pbrt-v4's named and sampled spectra in materials, as linear sRGB (named_spectra.h): the
// default conductor is copper; gold and copper reflect red most and blue least at normal
// incidence, silver over 90 % in every channel (their measured colours); BK7's index at 550 nm
// is 1.518 (Schott's catalogue: n_d = 1.5168 at 587.6 nm, rising towards the blue); a flat
// sampled spectrum is grey.
TEST(Pbrt, NamedAndSampledSpectraBecomeRgb) {
    const auto dir = test::scratch_dir("pbrt_spectra");
    const auto file = dir / "spectra.pbrt";
    const std::string triangle = kTriangle;
    write_file_atomically(
        file, std::string(kHeader) + "Material \"conductor\"\n" + triangle +
                  "Material \"conductor\" \"spectrum eta\" \"metal-Au-eta\" "
                  "\"spectrum k\" \"metal-Au-k\"\n" +
                  triangle +
                  "Material \"conductor\" \"spectrum eta\" \"metal-Ag-eta\" "
                  "\"spectrum k\" \"metal-Ag-k\"\n" +
                  triangle + "Material \"dielectric\" \"spectrum eta\" \"glass-BK7\"\n" + triangle +
                  "Material \"dielectric\" \"spectrum eta\" [200 1.45 900 1.45]\n" + triangle +
                  "Material \"diffuse\" \"spectrum reflectance\" [400 0.5 700 0.5]\n" + triangle);
    const Scene scene = load_scene(file);
    ASSERT_EQ(scene.shapes.size(), 6u);
    const auto material = [&](size_t i) { return scene.materials[scene.shapes[i].materials[0]]; };
    const auto f0 = [](const Material& m) {
        return ((m.eta - 1.0f) * (m.eta - 1.0f) + m.k * m.k) /
               ((m.eta + 1.0f) * (m.eta + 1.0f) + m.k * m.k);
    };
    for (size_t i : {0u, 1u}) {
        const glm::vec3 r = f0(material(i));
        SCOPED_TRACE(i == 0 ? "copper" : "gold");
        EXPECT_GT(r.r, r.g);
        EXPECT_GT(r.g, r.b);
        EXPECT_GT(r.r, 0.85f);
    }
    EXPECT_GT(glm::min(f0(material(2)).r, glm::min(f0(material(2)).g, f0(material(2)).b)), 0.9f);
    EXPECT_NEAR(material(3).ior, 1.5185f, 2e-3f);
    EXPECT_NEAR(material(4).ior, 1.45f, 1e-5f);
    EXPECT_NEAR(material(5).diffuse.r, 0.5f, 2e-3f);
    EXPECT_NEAR(material(5).diffuse.g, 0.5f, 2e-3f);
    EXPECT_NEAR(material(5).diffuse.b, 0.5f, 2e-3f);
}

// A light's "blackbody" [T] is Planck's spectrum at T kelvin made luminance 1 (pbrt-v4 divides a
// light's spectrum by its photometric integral), times "scale": checked against the CIE's own
// chromaticities of Planckian radiators (illuminant A, 2856 K: x 0.44757, y 0.40745; 6504 K, D65's
// correlated colour temperature, on the locus near x 0.3135, y 0.3237, CIE 15:2004 table T.2),
// read back through the standard sRGB-to-XYZ matrix (IEC 61966-2-1). A temperature that emits no
// light is refused in one line.
TEST(Pbrt, BlackbodyLightsHavePlanckChromaticityAndUnitLuminance) {
    const auto dir = test::scratch_dir("pbrt_blackbody");
    const auto file = dir / "blackbody.pbrt";
    write_file_atomically(file,
                          std::string(kHeader) +
                              "LightSource \"point\" \"blackbody I\" [2856] \"float scale\" 3\n"
                              "LightSource \"distant\" \"blackbody L\" [6504]\n" +
                              kTriangle);
    const Scene scene = load_scene(file);
    ASSERT_EQ(scene.emitters.size(), 3u);
    const auto xyz = [](glm::vec3 rgb) {
        return glm::dvec3(0.4124 * rgb.r + 0.3576 * rgb.g + 0.1805 * rgb.b,
                          0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b,
                          0.0193 * rgb.r + 0.1192 * rgb.g + 0.9505 * rgb.b);
    };
    const glm::dvec3 a = xyz(scene.emitters[1].intensity);
    EXPECT_NEAR(a.y, 3.0, 3e-3);
    EXPECT_NEAR(a.x / (a.x + a.y + a.z), 0.44757, 1e-3);
    EXPECT_NEAR(a.y / (a.x + a.y + a.z), 0.40745, 1e-3);
    const glm::dvec3 d = xyz(scene.emitters[2].irradiance);
    EXPECT_NEAR(d.y, 1.0, 1e-3);
    EXPECT_NEAR(d.x / (d.x + d.y + d.z), 0.3135, 1.5e-3);
    EXPECT_NEAR(d.y / (d.x + d.y + d.z), 0.3237, 1.5e-3);
    expect_refused(dir, "blackbody_zero",
                   std::string(kHeader) + "LightSource \"point\" \"blackbody I\" [0]\n",
                   "is not a temperature that emits visible light", 6, 1);
}

// A "spectrum" parameter naming a file reads pbrt-v4's spectrum file format (wavelength-value
// pairs separated by white space, '#' comments) relative to the scene's folder: the same colour
// and index as the same pairs given inline; a file that is not pairs is refused naming it.
TEST(Pbrt, SpectrumFilesReadAsTheirPairsInline) {
    const auto dir = test::scratch_dir("pbrt_spd");
    std::filesystem::create_directories(dir / "spds");
    const std::string pairs = "400 0.2 500 1.5 600 2.5 700 3";
    write_file_atomically(dir / "spds" / "eta.spd",
                          "# a made-up index\n400 0.2\n500\t1.5 # mid\n600 2.5\n700 3\n");
    write_file_atomically(dir / "spds" / "k.spd", "400 4 700 2\n");
    write_file_atomically(dir / "spds" / "odd.spd", "400 4 700\n");
    const std::string triangle = kTriangle;
    const auto file = dir / "spd.pbrt";
    write_file_atomically(
        file, std::string(kHeader) +
                  "Material \"conductor\" \"spectrum eta\" \"spds/eta.spd\" \"spectrum k\" "
                  "\"spds/k.spd\"\n" +
                  triangle + "Material \"conductor\" \"spectrum eta\" [" + pairs +
                  "] \"spectrum k\" [400 4 700 2]\n" + triangle +
                  "Material \"dielectric\" \"spectrum eta\" \"spds/eta.spd\"\n" + triangle);
    const Scene scene = load_scene(file);
    ASSERT_EQ(scene.shapes.size(), 3u);
    const auto material = [&](size_t i) { return scene.materials[scene.shapes[i].materials[0]]; };
    EXPECT_EQ(material(0).eta, material(1).eta);
    EXPECT_EQ(material(0).k, material(1).k);
    EXPECT_GT(material(0).eta.r, material(0).eta.b);  // the index rises with the wavelength
    EXPECT_NEAR(material(2).ior, 1.5f + 1.0f * 50.0f / 100.0f, 1e-5f);
    expect_refused(dir, "odd_spd",
                   std::string(kHeader) +
                       "Material \"conductor\" \"spectrum eta\" \"spds/odd.spd\"\n" + triangle,
                   "does not hold wavelength-value pairs", 6, 1);
}

// pbrt-v4's 2D checkerboard: tex1 where floor(uscale u + udelta) + floor(vscale v + vdelta) is
// even, tex2 elsewhere (pbrt-v4's Checkerboard without its filtering), baked into a texture
// radcache's uv lookup repeats; `convert` refuses it by name; a scale it cannot bake is refused.
TEST(Pbrt, CheckerboardTextureIsBakedAsPbrtV4DefinesIt) {
    const auto dir = test::scratch_dir("pbrt_checkerboard");
    const auto file = dir / "checks.pbrt";
    const std::string checks =
        "Texture \"c\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [0.8 0.1 0.1]\n"
        "    \"rgb tex2\" [0.1 0.1 0.8] \"float uscale\" 4 \"float vscale\" 2 "
        "\"float udelta\" 0.5\n"
        "Material \"diffuse\" \"texture reflectance\" \"c\"\n";
    write_file_atomically(file, std::string(kHeader) + checks + kTriangle);
    const Scene scene = load_scene(file);
    const Material& m = scene.materials[scene.shapes[0].materials[0]];
    ASSERT_GE(m.diffuse_texture, 0);
    const Texture& t = scene.textures[m.diffuse_texture];
    ASSERT_EQ(t.width, 32);
    ASSERT_EQ(t.height, 16);
    for (const auto& [u, v] : {std::pair{0.05, 0.1}, std::pair{0.2, 0.1}, std::pair{0.05, 0.6},
                               std::pair{0.9, 0.9}, std::pair{0.6, 0.3}}) {
        const bool even =
            (static_cast<int>(std::floor(4 * u + 0.5)) + static_cast<int>(std::floor(2 * v))) % 2 ==
            0;
        const int x = static_cast<int>(u * t.width);
        const int y = static_cast<int>((1.0 - v) * t.height);  // rows top to bottom
        EXPECT_FLOAT_EQ(t.texels[y * t.width + x].r, even ? 0.8f : 0.1f) << u << ", " << v;
        EXPECT_FLOAT_EQ(t.texels[y * t.width + x].b, even ? 0.1f : 0.8f) << u << ", " << v;
    }
    const test::CommandResult converted =
        test::run_radcache({"convert", file.string(), (dir / "checks.json").string(), "-q"});
    EXPECT_NE(converted.exit_code, 0);
    EXPECT_NE(converted.output.find("procedural texture"), std::string::npos) << converted.output;
    expect_refused(dir, "fractional_scale",
                   std::string(kHeader) +
                       "Texture \"c\" \"spectrum\" \"checkerboard\" \"float uscale\" 2.5\n" +
                       "Material \"diffuse\" \"texture reflectance\" \"c\"\n" + kTriangle,
                   "a checkerboard scale must be a whole number", 6, 2);
}

// pbrt-v3's Film "image" is the RGB film (pbrt-v4's --upgrade renames it): its resolution is
// read as "rgb"'s; another film name is still refused, naming both lists.
TEST(Pbrt, PbrtV3ImageFilmIsTheRgbFilm) {
    const auto dir = test::scratch_dir("pbrt_v3_film");
    const auto file = dir / "v3.pbrt";
    const std::string rest = std::string("LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\n") +
                             "WorldBegin\nLightSource \"point\" \"point3 from\" [0 0 -4]\n" +
                             kTriangle;
    write_file_atomically(
        file, "Film \"image\" \"integer xresolution\" 40 \"integer yresolution\" 20\n" + rest);
    const Scene scene = load_scene(file);
    EXPECT_EQ(scene.camera.width, 40);
    EXPECT_EQ(scene.camera.height, 20);
    expect_refused(dir, "film_foo", "Film \"foo\"\n" + rest,
                   "is not one of pbrt-v4's films (rgb, gbuffer, spectral) or pbrt-v3's image", 1,
                   1);
}

// A textured diffuse transmitter: a texture of texels c on its reflectance, its transmittance or
// both renders, seen from the lit side and from behind, the image of the same transmitter with c
// given as constants (pt, the same seed: the same paths, so within float rounding); two different
// textures on the two lobes are refused.
TEST(Pbrt, TexturedDiffuseTransmissionScalesItsLobes) {
    const auto dir = test::scratch_dir("pbrt_textured_transmission");
    const std::string texture =
        "Texture \"c\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [0.3 0.4 0.5]\n"
        "    \"rgb tex2\" [0.3 0.4 0.5]\n";
    const std::string plane =
        "Shape \"trianglemesh\" \"point3 P\" [-1 -1 0 1 -1 0 1 1 0 -1 1 0]\n"
        "    \"integer indices\" [0 1 2 0 2 3] \"point2 uv\" [0 0 1 0 1 1 0 1]\n";
    const auto scene = [&](const std::string& name, const std::string& eye,
                           const std::string& material) {
        const auto file = dir / (name + ".pbrt");
        write_file_atomically(
            file, "LookAt " + eye + "  0 0 0  0 1 0\nCamera \"perspective\"\n" +
                      "WorldBegin\nLightSource \"point\" \"point3 from\" [0.3 0.2 -2]\n" + texture +
                      "Material \"diffusetransmission\" " + material + "\n" + plane);
        return render(file, dir / (name + ".exr"), {"--width", "16", "--height", "16"});
    };
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"\"texture reflectance\" \"c\" \"texture transmittance\" \"c\"",
         "\"rgb reflectance\" [0.3 0.4 0.5] \"rgb transmittance\" [0.3 0.4 0.5]"},
        {"\"texture reflectance\" \"c\" \"rgb transmittance\" [0.5 0.4 0.3]",
         "\"rgb reflectance\" [0.3 0.4 0.5] \"rgb transmittance\" [0.5 0.4 0.3]"},
        {"\"rgb reflectance\" [0.2 0.2 0.2] \"texture transmittance\" \"c\" \"float scale\" 2",
         "\"rgb reflectance\" [0.2 0.2 0.2] \"rgb transmittance\" [0.3 0.4 0.5] "
         "\"float scale\" 2"}};
    for (size_t i = 0; i < cases.size(); ++i) {
        for (const char* eye : {"0 0 -3", "0 0 3"}) {
            const std::string name = "case" + std::to_string(i) + (eye[4] == '-' ? "f" : "b");
            const Image textured = scene(name + "t", eye, cases[i].first);
            const Image constant = scene(name + "c", eye, cases[i].second);
            double largest = 0.0, difference = 0.0;
            for (int y = 0; y < constant.height; ++y) {
                for (int x = 0; x < constant.width; ++x) {
                    for (int c = 0; c < 3; ++c) {
                        largest = std::max(largest, double(constant.at(x, y, c)));
                        difference =
                            std::max(difference,
                                     std::abs(double(textured.at(x, y, c) - constant.at(x, y, c))));
                    }
                }
            }
            EXPECT_GT(largest, 0.0) << name;
            EXPECT_LE(difference, 1e-5 * largest) << name;
        }
    }
    write_file_atomically(dir / "d.png", read_file(data("checker.png")));
    expect_refused(dir, "two_textures",
                   std::string(kHeader) + texture +
                       "Texture \"d\" \"spectrum\" \"imagemap\" \"string filename\" \"d.png\"\n" +
                       "Material \"diffusetransmission\" \"texture reflectance\" \"c\" "
                       "\"texture transmittance\" \"d\"\n" +
                       kTriangle,
                   "from two different textures are not supported", 9, 2);
}

// pbrt-v4's "scale" texture: tex x scale, a reflectance clamped to [0, 1] as pbrt-v4's materials
// clamp it: a scale that keeps the texels within 1 reuses the texture under that scale, one that
// would exceed 1 bakes the clamped product; a constant is scaled and clamped; a textured scale is
// refused.
TEST(Pbrt, ScaleTextureMultipliesAndClampsAsPbrtV4) {
    const auto dir = test::scratch_dir("pbrt_scale_texture");
    const auto file = dir / "scale.pbrt";
    const std::string triangle = kTriangle;
    write_file_atomically(
        file,
        std::string(kHeader) +
            "Texture \"c\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [0.8 0.4 0.1]\n"
            "    \"rgb tex2\" [0.1 0.1 0.1]\n"
            "Texture \"half\" \"spectrum\" \"scale\" \"texture tex\" \"c\" \"float scale\" 0.5\n"
            "Texture \"double\" \"spectrum\" \"scale\" \"texture tex\" \"c\" \"float scale\" 2\n"
            "Texture \"k\" \"spectrum\" \"scale\" \"rgb tex\" [0.6 0.3 0.1] \"float scale\" 2\n"
            "Material \"diffuse\" \"texture reflectance\" \"half\"\n" +
            triangle + "Material \"diffuse\" \"texture reflectance\" \"double\"\n" + triangle +
            "Material \"diffuse\" \"texture reflectance\" \"k\"\n" + triangle +
            "Material \"diffuse\" \"texture reflectance\" \"c\"\n" + triangle);
    const Scene scene = load_scene(file);
    ASSERT_EQ(scene.shapes.size(), 4u);
    const auto material = [&](size_t i) { return scene.materials[scene.shapes[i].materials[0]]; };
    const Material checks = material(3);
    ASSERT_GE(checks.diffuse_texture, 0);
    EXPECT_EQ(material(0).diffuse_texture, checks.diffuse_texture);
    expect_near(material(0).diffuse, glm::vec3(0.5f), "half");
    const Material doubled = material(1);
    ASSERT_GE(doubled.diffuse_texture, 0);
    ASSERT_NE(doubled.diffuse_texture, checks.diffuse_texture);
    expect_near(doubled.diffuse, glm::vec3(1.0f), "doubled's factor");
    const Texture& original = scene.textures[checks.diffuse_texture];
    const Texture& baked = scene.textures[doubled.diffuse_texture];
    ASSERT_EQ(baked.texels.size(), original.texels.size());
    for (size_t i = 0; i < baked.texels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_FLOAT_EQ(baked.texels[i][c], std::min(1.0f, 2.0f * original.texels[i][c]));
        }
    }
    EXPECT_FLOAT_EQ(baked.max_value, 1.0f);
    EXPECT_LT(material(2).diffuse_texture, 0);
    expect_near(material(2).diffuse, glm::vec3(1.0f, 0.6f, 0.2f), "scaled constant");
    expect_refused(dir, "textured_scale",
                   std::string(kHeader) +
                       "Texture \"c\" \"spectrum\" \"scale\" \"texture scale\" \"x\"\n" +
                       "Material \"diffuse\" \"texture reflectance\" \"c\"\n" + triangle,
                   "has a textured \"scale\"", 7, 2);
}

TEST(Pbrt, LightsTakePowerIlluminanceAndDirectionAsPbrtV4) {
    const auto dir = test::scratch_dir("pbrt_lights");
    const auto file = dir / "lights.pbrt";
    write_file_atomically(
        file,
        std::string(kHeader) + kTriangle +
            "LightSource \"point\" \"rgb I\" [1 0.5 0.25] \"float power\" 100\n"
            "LightSource \"spot\" \"rgb I\" [2 2 2] \"float scale\" 0.5 \"float power\" 50\n"
            "    \"float coneangle\" 40 \"float conedeltaangle\" 10\n"
            "AttributeBegin\n  Rotate 90 0 0 1\n"
            "  LightSource \"distant\" \"point3 from\" [0 0 0] \"point3 to\" [1 1 -1]\n"
            "      \"rgb L\" [1 2 3] \"float scale\" 2 \"float illuminance\" 10\n"
            "AttributeEnd\n"
            "LightSource \"infinite\" \"rgb L\" [0.5 1 1] \"float illuminance\" 3.14159265\n");
    const Scene scene = load_scene(file);
    ASSERT_EQ(scene.emitters.size(), 5u);  // the header's point light first
    const double pi = 3.14159265358979;
    expect_near(scene.emitters[1].intensity,
                glm::vec3(1, 0.5f, 0.25f) * static_cast<float>(100 / (4 * pi)), "point power");
    const double start = std::cos(30 * pi / 180);
    const double end = std::cos(40 * pi / 180);
    const double k_e = 2 * pi * ((1 - start) + (start - end) / 2);
    expect_near(scene.emitters[2].intensity, glm::vec3(static_cast<float>(50 / k_e)), "spot power");
    EXPECT_FLOAT_EQ(scene.emitters[2].beam_width, 30.0f);
    const Emitter& sun = scene.emitters[3];
    EXPECT_EQ(sun.kind, EmitterKind::kDistant);
    expect_near(sun.irradiance, glm::vec3(20, 40, 60), "distant illuminance");
    // (1, 1, -1) rotated 90 degrees about z: (-1, 1, -1); pbrt's x mirrored: (1, 1, -1).
    expect_near(sun.direction, glm::vec3(1, 1, -1) / std::sqrt(3.0f), "distant direction");
    EXPECT_EQ(scene.emitters[4].kind, EmitterKind::kConstant);
    expect_near(scene.emitters[4].radiance, glm::vec3(0.5f, 1, 1), "infinite illuminance");
    // A distant light without a direction: one line naming the file and line.
    expect_refused(dir, "no_direction",
                   std::string(kHeader) + "LightSource \"distant\" \"point3 to\" [0 0 0]\n",
                   "\"from\" and \"to\" give no direction", 6);
    expect_refused(dir, "wide_delta",
                   std::string(kHeader) +
                       "LightSource \"spot\" \"float coneangle\" 20 \"float conedeltaangle\" 30\n",
                   "conedeltaangle must lie in [0, coneangle]", 6);
}

// pbrt-v4's disk as an area light: a disk of radius R = 1 and radiance L = 2 (its surface normal,
// pbrt's +z, turned down) a distance d = 1 above a diffuse floor of reflectance 0.5 gives the
// point below its centre E = pi L R^2 / (d^2 + R^2) = pi, radiance rho E / pi = 0.5. The camera
// sees only floor points within 0.01 of it (their irradiance within 1e-4 of the centre's); the
// disk is black, so nothing but its light reaches the floor. A disk wound the wrong way emits
// nothing towards the floor; a tessellation losing area shows as less light. At 1 024 samples a
// pixel (light samples of the disk by solid angle) a pixel's noise is about 1 % (measured: every
// pixel within 0.8 % at 4 096), the image mean's under 0.05 %: pixels within 4 %, the mean within
// 0.5 %.
TEST(Pbrt, DiskAreaLightGivesTheClosedFormIrradiance) {
    const auto dir = test::scratch_dir("pbrt_disk");
    const auto file = dir / "disk.pbrt";
    write_file_atomically(file,
                          "LookAt 0 0.5 0  0 0 0  0 0 1\nCamera \"perspective\" \"float fov\" 2\n"
                          "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
                          "Sampler \"independent\" \"integer pixelsamples\" 256\n"
                          "WorldBegin\n"
                          "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
                          "Shape \"trianglemesh\" \"point3 P\" [-5 0 -5  5 0 -5  5 0 5  -5 0 5]\n"
                          "    \"integer indices\" [0 1 2 0 2 3]\n"
                          "AttributeBegin\n"
                          "  Material \"diffuse\" \"rgb reflectance\" [0 0 0]\n"
                          "  AreaLightSource \"diffuse\" \"rgb L\" [2 2 2]\n"
                          "  Translate 0 1 0\n  Rotate 90 1 0 0\n"
                          "  Shape \"disk\" \"float radius\" 1\n"
                          "AttributeEnd\n");
    const Scene scene = load_scene(file);
    ASSERT_EQ(scene.lights.lights.size(), 1u);
    const double pi = 3.14159265358979;
    EXPECT_NEAR(scene.lights.lights[0].area, pi, 1.01e-4 * pi);
    const test::CommandResult result = test::run_radcache(
        {"render", file.string(), "-o", (dir / "disk.exr").string(), "--spp", "1024", "-q"});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Image image = read_image(dir / "disk.exr");
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            ASSERT_NEAR(image.at(x, y, 0), 0.5, 0.02) << x << ", " << y;
            sum += image.at(x, y, 0);
        }
    }
    EXPECT_NEAR(sum / (image.width * image.height), 0.5, 0.0025);
    // The disk's and cylinder's parameters out of range: one line naming the file and line.
    for (const auto& [name, shape, expected] :
         {std::tuple<std::string, std::string, std::string>{
              "disk_radius", "Shape \"disk\" \"float radius\" 0\n", "radius must be positive"},
          {"disk_hole", "Shape \"disk\" \"float radius\" 1 \"float innerradius\" 1\n",
           "innerradius must lie in [0, radius)"},
          {"disk_phimax", "Shape \"disk\" \"float phimax\" 0\n", "phimax must lie in (0, 360]"},
          {"cylinder_height", "Shape \"cylinder\" \"float zmin\" 1 \"float zmax\" 1\n",
           "zmin and zmax must be finite and differ"}}) {
        expect_refused(dir, name, std::string(kHeader) + shape, expected, 6);
    }
}

// Wrong values, truncated files and missing files: one line naming the file (and the line).
TEST(Pbrt, MalformedInputsAreRefusedCleanly) {
    const auto dir = test::scratch_dir("pbrt_malformed");
    const std::string head = kHeader;
    expect_refused(dir, "unterminated", head + "Shape \"trianglemesh\n\"point3 P\" [0 0 0]\n",
                   "unterminated string \"trianglemesh\"", 6);
    expect_refused(dir, "bracket", head + "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0\n",
                   "expected a value or ']', got the end of the file", 6);
    expect_refused(dir, "type", head + "Shape \"trianglemesh\" \"point3 P\" \"zero\"\n",
                   "expected numbers, got a string", 6);
    expect_refused(dir, "fov_type", "Camera \"perspective\" \"integer fov\" 45\nWorldBegin\n",
                   "parameter \"fov\" must be of type float, not integer", 1);
    expect_refused(dir, "indices",
                   head +
                       "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] "
                       "\"integer indices\" [0 1 3]\n",
                   "index 3 out of range (3 vertices)", 6);
    expect_refused(dir, "include", head + "Include \"nowhere.pbrt\"\n", "file not found", 6);
    expect_refused(dir, "twice", "Camera \"perspective\" \"float fov\" 45 \"float fov\" 50\n",
                   "parameter \"fov\" is given twice", 1);
    expect_refused(dir, "no_world", "Camera \"perspective\"\n", "has no WorldBegin", 0);
    expect_refused(dir, "unbalanced", head + "AttributeEnd\n",
                   "AttributeEnd without a matching AttributeBegin", 6);
    expect_refused(dir, "unclosed", head + "AttributeBegin\n",
                   "AttributeBegin has no matching AttributeEnd", 6);
    expect_refused(dir, "unclosed_transform",
                   head + "TransformBegin\nAttributeBegin\nAttributeEnd\n",
                   "TransformBegin has no matching TransformEnd", 6);
    expect_refused(dir, "material_twice",
                   head +
                       "MakeNamedMaterial \"a\" \"string type\" \"diffuse\"\n"
                       "MakeNamedMaterial \"a\" \"string type\" \"conductor\"\n",
                   "MakeNamedMaterial \"a\": a material of that name is already defined", 7);
    // An include cycle stops at the nesting limit.
    write_file_atomically(dir / "self.pbrt", head + "Include \"self.pbrt\"\n");
    expect_refused(dir, "self", head + "Include \"self.pbrt\"\n", "nested deeper", 0);
    // A PLY whose header declares more than its file holds, and one without end_header (on
    // which Assimp 5.2 loops without end: radcache checks the header first).
    std::string huge = ascii_ply();
    huge.replace(huge.find("element vertex 5"), 16, "element vertex 500000");
    write_file_atomically(dir / "huge.ply", huge);
    expect_refused(dir, "huge", head + "Shape \"plymesh\" \"string filename\" \"huge.ply\"\n",
                   "its elements need at least", 6);
    write_file_atomically(dir / "headless.ply",
                          "ply\nformat ascii 1.0\nelement vertex 5\n"
                          "property float x\nprop 1 2 3\n3 1 4 2\n");
    expect_refused(dir, "headless",
                   head + "Shape \"plymesh\" \"string filename\" \"headless.ply\"\n",
                   "no \"ply\" ... \"end_header\" header", 6);
    // A .ply.gz that is not gzip data past its magic number, and one cut short.
    const std::string gz = gzipped(binary_ply());
    for (const auto& [name, bytes, expected] :
         {std::tuple<std::string, std::string, std::string>{
              "gz_corrupt", std::string("\x1f\x8b") + std::string(40, 'x'), "corrupt"},
          {"gz_cut", gz.substr(0, gz.size() / 2), "truncated"}}) {
        write_file_atomically(dir / (name + ".ply.gz"), bytes);
        expect_refused(dir, name,
                       head + "Shape \"plymesh\" \"string filename\" \"" + name + ".ply.gz\"\n",
                       "not valid gzip data (" + expected + ")", 6);
    }
    // Truncated PLY files: the ASCII one ends inside its vertices, the binary one in its faces.
    for (const auto& [name, ply] :
         {std::pair{"ascii_cut", ascii_ply().substr(0, ascii_ply().size() - 40)},
          {"binary_cut", binary_ply().substr(0, binary_ply().size() - 6)}}) {
        write_file_atomically(dir / (std::string(name) + ".ply"), ply);
        expect_refused(dir, name,
                       head + "Shape \"plymesh\" \"string filename\" \"" + name + ".ply\"\n", "PLY",
                       6);
    }
}

// A parameter the import does not know is one warning naming it; --strict makes it an error.
TEST(Pbrt, UnsupportedParametersWarnAndStrictRefuses) {
    const auto dir = test::scratch_dir("pbrt_warn");
    const auto file = dir / "warn.pbrt";
    write_file_atomically(file, std::string(kHeader) +
                                    "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] "
                                    "\"vector3 S\" [1 0 0 1 0 0 1 0 0]\n");
    const test::CommandResult result =
        test::run_radcache({"render", file.string(), "-o", (dir / "out.png").string(), "--spp", "1",
                            "--width", "8", "--height", "8"});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find(file.string() +
                                 ":6: Shape \"trianglemesh\": parameter \"vector3 S\" is not "
                                 "supported and ignored"),
              std::string::npos)
        << result.output;
    const test::CommandResult strict = test::run_radcache(
        {"render", file.string(), "-o", (dir / "strict.png").string(), "--spp", "1", "--strict"});
    EXPECT_NE(strict.exit_code, 0);
    EXPECT_FALSE(std::filesystem::exists(dir / "strict.png"));
}

TEST(Pbrt, ConvertedSceneRendersBitwiseAsThePbrt) {
    const auto dir = test::scratch_dir("pbrt_convert");
    for (const std::string name : {"cornell-box", "hierarchy"}) {
        const test::CommandResult result = test::run_radcache(
            {"convert", data(name + ".pbrt").string(), (dir / (name + ".json")).string(), "-q"});
        ASSERT_EQ(result.exit_code, 0) << result.output;
        const Image pbrt = render(data(name + ".pbrt"), dir / (name + "-p.exr"));
        const Image json = render(dir / (name + ".json"), dir / (name + "-j.exr"));
        EXPECT_TRUE(test::bitwise_equal(pbrt, json)) << name;
        // The pbrt scene's render settings travel with it.
        EXPECT_EQ(load_scene(dir / (name + ".json")).render.max_depth,
                  load_scene(data(name + ".pbrt")).render.max_depth);
    }
}

// The fuzz target's seeds (tests/fuzz/seeds/pbrt/) are whole scenes the import accepts, so that
// fuzzing starts from inputs that reach every stage.
TEST(Pbrt, FuzzSeedsAreScenesTheImportAccepts) {
    const auto seeds = test::source_dir() / "tests/fuzz/seeds/pbrt";
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(seeds)) {
        SCOPED_TRACE(entry.path().string());
        const std::string input = read_file(entry.path());
        MemoryFiles files;
        for (auto& [name, bytes] : fuzz::split_files(reinterpret_cast<const uint8_t*>(input.data()),
                                                     input.size(), "scene.pbrt")) {
            files.add(name, std::move(bytes));
        }
        const Scene scene = load_pbrt_scene("scene.pbrt", files);
        EXPECT_GT(scene.mesh.triangle_count(), 0u);
        EXPECT_FALSE(scene.lights.lights.empty());
        ++count;
    }
    EXPECT_GE(count, 5);
}

}  // namespace
}  // namespace rc
