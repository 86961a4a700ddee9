#include "scene/pbrt_loader.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <map>
#include <optional>

#include "scene/environment_map.h"
#include "scene/pbrt_materials.h"
#include "scene/pbrt_params.h"
#include "scene/pbrt_shapes.h"
#include "scene/transform.h"
#include "util/error.h"
#include "util/log.h"
#include "util/text.h"

namespace rc {
namespace {

constexpr float kPi = 3.14159265f;

// The most triangles object instancing and tessellated spheres may add (a file of a few
// kilobytes must not instance its way to exhausting memory).
constexpr size_t kMaxCopiedTriangles = size_t{1} << 24;

std::string in_quotes(const std::string& text) { return "\"" + excerpt(text) + "\""; }

// The attributes AttributeBegin saves and AttributeEnd restores.
struct Attributes {
    glm::dmat4 ctm{1.0};
    bool reverse_orientation = false;
    int material = -1;  // a PbrtMaterials handle; -1: pbrt's default (diffuse 0.5)
    std::optional<glm::vec3> area_radiance;
    bool saves_transform_only = false;  // pushed by TransformBegin
    std::string opened_at;              // file:line of the directive that pushed it
};

// pbrt's LookAt: the camera-from-world transform of a camera at `eye` looking at `at`.
glm::dmat4 look_at(const PbrtDirective& d) {
    const glm::dvec3 eye(d.numbers[0], d.numbers[1], d.numbers[2]);
    const glm::dvec3 at(d.numbers[3], d.numbers[4], d.numbers[5]);
    const glm::dvec3 up(d.numbers[6], d.numbers[7], d.numbers[8]);
    if (!(glm::length(at - eye) > 0.0) || !(glm::length(up) > 0.0)) {
        throw Error(d.where() + ": LookAt: the eye coincides with the target, or up is zero");
    }
    const glm::dvec3 dir = glm::normalize(at - eye);
    const glm::dvec3 side = glm::cross(glm::normalize(up), dir);
    if (!(glm::length(side) > 1e-9)) {
        throw Error(d.where() + ": LookAt: up is parallel to the viewing direction");
    }
    const glm::dvec3 right = glm::normalize(side);
    const glm::dvec3 new_up = glm::cross(dir, right);
    glm::dmat4 world_from_camera(1.0);
    world_from_camera[0] = glm::dvec4(right, 0.0);
    world_from_camera[1] = glm::dvec4(new_up, 0.0);
    world_from_camera[2] = glm::dvec4(dir, 0.0);
    world_from_camera[3] = glm::dvec4(eye, 1.0);
    return glm::inverse(world_from_camera);
}

// Each triangle of an emitting mesh with normals wound so that its front (radcache's emitting
// side) is the normals' side: pbrt's area lights emit on the side of the shading normal.
void orient_to_normals(TriangleMesh& mesh) {
    if (mesh.normals.empty()) {
        return;
    }
    for (glm::uvec3& t : mesh.triangles) {
        const glm::vec3 winding = glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                             mesh.positions[t.z] - mesh.positions[t.x]);
        const glm::vec3 normal = mesh.normals[t.x] + mesh.normals[t.y] + mesh.normals[t.z];
        if (glm::dot(winding, normal) < 0.0f) {
            std::swap(t.y, t.z);
        }
    }
}

class PbrtSceneBuilder {
   public:
    PbrtSceneBuilder(const std::filesystem::path& path, const SceneFiles& files, Scene& scene)
        : file_(path.string()),
          dir_(path.parent_path()),
          files_(files),
          scene_(scene),
          materials_(scene, files, path.parent_path()) {}

    void build(const std::vector<PbrtDirective>& directives) {
        for (const PbrtDirective& d : directives) {
            if (!transform_directive(d) && !options_directive(d)) {
                world_directive(d);
            }
        }
        if (!in_world_) {
            throw Error(file_ + ": the file has no WorldBegin");
        }
        if (object_) {
            throw Error(file_ + ": ObjectBegin " + in_quotes(object_name_) + " has no ObjectEnd");
        }
        if (!stack_.empty()) {
            const bool transform = stack_.back().saves_transform_only;
            throw Error(stack_.back().opened_at + ": " +
                        (transform ? "TransformBegin has no matching TransformEnd"
                                   : "AttributeBegin has no matching AttributeEnd"));
        }
    }

   private:
    // Translate, Scale, Rotate, LookAt, Transform, ConcatTransform, Identity, CoordinateSystem,
    // CoordSysTransform, TransformBegin/End, ActiveTransform, TransformTimes.
    bool transform_directive(const PbrtDirective& d) {
        const std::vector<double>& n = d.numbers;
        glm::dmat4& ctm = attributes_.ctm;
        if (d.name == "Translate") {
            ctm = glm::translate(ctm, glm::dvec3(n[0], n[1], n[2]));
        } else if (d.name == "Scale") {
            ctm = glm::scale(ctm, glm::dvec3(n[0], n[1], n[2]));
        } else if (d.name == "Rotate") {
            const glm::dvec3 axis(n[1], n[2], n[3]);
            if (!(glm::length(axis) > 0.0)) {
                throw Error(d.where() + ": Rotate about the zero vector");
            }
            ctm = glm::rotate(ctm, glm::radians(n[0]), glm::normalize(axis));
        } else if (d.name == "LookAt") {
            ctm = ctm * look_at(d);
        } else if (d.name == "Transform" || d.name == "ConcatTransform") {
            const glm::dmat4 m = glm::make_mat4(n.data());  // pbrt's 16 numbers: column-major
            ctm = d.name == "Transform" ? m : ctm * m;
        } else if (d.name == "Identity") {
            ctm = glm::dmat4(1.0);
        } else if (d.name == "CoordinateSystem") {
            named_[d.strings[0]] = ctm;
        } else if (d.name == "CoordSysTransform") {
            const auto found = named_.find(d.strings[0]);
            if (found == named_.end()) {
                throw Error(d.where() + ": CoordSysTransform: no coordinate system named " +
                            in_quotes(d.strings[0]));
            }
            ctm = found->second;
        } else if (d.name == "TransformBegin") {
            stack_.push_back(attributes_);
            stack_.back().saves_transform_only = true;
            stack_.back().opened_at = d.where();
        } else if (d.name == "TransformEnd") {
            if (stack_.empty() || !stack_.back().saves_transform_only) {
                throw Error(d.where() + ": TransformEnd without a matching TransformBegin");
            }
            ctm = stack_.back().ctm;
            stack_.pop_back();
        } else if (d.name == "ActiveTransform") {
            if (d.strings[0] != "All") {
                throw Error(d.where() + ": ActiveTransform " + excerpt(d.strings[0]) +
                                ": animated transforms (motion blur) are not supported",
                            kExitUnsupported);
            }
        } else if (d.name != "TransformTimes") {  // times only matter to animated transforms
            return false;
        }
        if (!std::isfinite(ctm[0][0] + ctm[1][1] + ctm[2][2] + ctm[3][0] + ctm[3][1] + ctm[3][2])) {
            throw Error(d.where() + ": " + d.name + ": the transform overflows");
        }
        return true;
    }

    void require(const PbrtDirective& d, bool world) const {
        if (in_world_ != world) {
            throw Error(d.where() + ": " + d.name + " is not allowed " +
                        (world ? "before WorldBegin" : "after WorldBegin"));
        }
    }

    // The rendering options before WorldBegin.
    bool options_directive(const PbrtDirective& d) {
        // The directives allowed only before WorldBegin, each read by its handler.
        using Handler = void (PbrtSceneBuilder::*)(const PbrtDirective&);
        static const std::map<std::string, Handler> kHandlers = {
            {"Camera", &PbrtSceneBuilder::camera},
            {"Film", &PbrtSceneBuilder::film},
            {"Sampler", &PbrtSceneBuilder::sampler},
            {"Integrator", &PbrtSceneBuilder::integrator},
            {"PixelFilter", &PbrtSceneBuilder::pixel_filter},
            {"WorldBegin", &PbrtSceneBuilder::world_begin}};
        if (const auto handler = kHandlers.find(d.name); handler != kHandlers.end()) {
            require(d, false);
            (this->*handler->second)(d);
        } else if (d.name == "Accelerator") {
            require(d, false);  // radcache builds its own BVH
        } else if (d.name == "Option") {
            PbrtParams(d, d.where() + ": Option").warn_unused();
        } else if (d.name == "ColorSpace") {
            if (d.strings[0] != "srgb") {
                throw Error(d.where() + ": ColorSpace " + in_quotes(d.strings[0]) +
                                " is not supported (radcache renders in linear sRGB)",
                            kExitUnsupported);
            }
        } else {
            return false;
        }
        return true;
    }

    void camera(const PbrtDirective& d) {
        const std::string what = d.where() + ": Camera " + in_quotes(d.strings[0]);
        if (d.strings[0] != "perspective") {
            throw Error(what + " is not supported (perspective is)", kExitUnsupported);
        }
        PbrtParams params(d, what);
        const float fov = params.get_float("fov", 90.0f);
        if (!(fov > 0.0f && fov < 180.0f)) {
            params.fail("fov must lie strictly between 0 and 180 degrees");
        }
        camera_.fov_degrees = fov;
        camera_.fov_axis = FovAxis::kSmaller;  // pbrt's fov spans the shorter image axis
        if (params.get_float("lensradius", 0.0f) > 0.0f) {
            log_warning(what +
                        ": depth of field (lensradius) is not supported: rendered as a "
                        "pinhole camera");
        }
        for (const char* ignored : {"focaldistance", "shutteropen", "shutterclose"}) {
            params.ignore(ignored);
        }
        params.warn_unused();
        camera_from_world_ = attributes_.ctm;
        named_["camera"] = glm::inverse(attributes_.ctm);
    }

    void film(const PbrtDirective& d) {
        const std::string what = d.where() + ": Film " + in_quotes(d.strings[0]);
        // "image" is pbrt-v3's name of the RGB film (pbrt-v4's --upgrade renames it "rgb").
        if (d.strings[0] != "rgb" && d.strings[0] != "gbuffer" && d.strings[0] != "spectral" &&
            d.strings[0] != "image") {
            throw Error(what + " is not one of pbrt-v4's films (rgb, gbuffer, spectral) or " +
                        "pbrt-v3's image");
        }
        PbrtParams params(d, what);
        for (const char* axis : {"xresolution", "yresolution"}) {
            const int value = params.get_int(axis, axis[0] == 'x' ? 1280 : 720);
            if (value < 1 || value > kMaxImageSide) {
                params.fail(std::string(axis) + " must lie in [1, " +
                            std::to_string(kMaxImageSide) + "]");
            }
            (axis[0] == 'x' ? camera_.width : camera_.height) = value;
        }
        const std::string filename = params.get_string("filename", "");
        if (!filename.empty()) {
            log_note(what + ": filename " + in_quotes(filename) +
                     " ignored (radcache writes the image -o names)");
        }
        params.ignore("diagonal");  // the realistic camera's only
        params.ignore("savefp16");
        params.warn_unused();
    }

    void sampler(const PbrtDirective& d) {
        const std::string& type = d.strings[0];
        const std::string what = d.where() + ": Sampler " + in_quotes(type);
        PbrtParams params(d, what);
        if (type == "independent") {
            camera_.sampler = RC_SAMPLER_INDEPENDENT;
        } else if (type == "zsobol" || type == "sobol" || type == "paddedsobol" ||
                   type == "halton" || type == "pmj02bn" || type == "stratified") {
            camera_.sampler = RC_SAMPLER_SOBOL;
        } else {
            throw Error(what + " is not one of pbrt-v4's samplers");
        }
        if (type == "stratified") {
            spp_ = static_cast<long long>(params.get_int("xsamples", 4)) *
                   params.get_int("ysamples", 4);
            params.ignore("jitter");
        } else {
            spp_ = params.get_int("pixelsamples", 16);
        }
        spp_where_ = what;
        if (params.has("seed")) {
            seed_ = params.get_int("seed", 0);
        }
        params.ignore("randomization");
        params.warn_unused();
    }

    void integrator(const PbrtDirective& d) {
        const std::string& type = d.strings[0];
        const std::string what = d.where() + ": Integrator " + in_quotes(type);
        static const char* kConverging[] = {"volpath",    "path",       "bdpt",
                                            "mlt",        "sppm",       "lightpath",
                                            "simplepath", "randomwalk", "simplevolpath"};
        if (std::find(std::begin(kConverging), std::end(kConverging), type) ==
            std::end(kConverging)) {
            throw Error(what +
                            " is not supported (radcache renders the light transport image "
                            "that path, volpath, bdpt, mlt and sppm converge to)",
                        kExitUnsupported);
        }
        PbrtParams params(d, what);
        max_depth_ = params.get_int("maxdepth", 5);
        max_depth_where_ = what;
        if (params.get_bool("regularize", false)) {
            log_warning(what + ": \"regularize\" is not supported: rendered unregularized");
        }
        params.ignore("lightsampler");  // a sampling strategy: the image is the same
        params.warn_unused();
    }

    void pixel_filter(const PbrtDirective& d) {
        const std::string& type = d.strings[0];
        const std::string what = d.where() + ": PixelFilter " + in_quotes(type);
        PbrtParams params(d, what);
        const int filter = type == "triangle" ? RC_FILTER_TENT : pixel_filter_type(type);
        if (filter < 0 || type == "tent") {
            throw Error(what + " is not supported (box, triangle, gaussian)", kExitUnsupported);
        }
        const float fallback = filter == RC_FILTER_TENT ? 2.0f : default_filter_radius(filter);
        const float x = params.get_float("xradius", fallback);
        const float y = params.get_float("yradius", fallback);
        if (x != y) {
            params.refuse("xradius and yradius differ (radcache's filters are square)");
        }
        if (!(x >= kMinFilterRadius && x <= kMaxFilterRadius)) {
            params.fail("the radius must lie in [" + std::to_string(kMinFilterRadius) + ", " +
                        std::to_string(kMaxFilterRadius) + "] pixels");
        }
        if (filter == RC_FILTER_GAUSSIAN) {
            const float sigma = params.get_float("sigma", 0.5f);
            if (std::abs(sigma - x / 3.0f) > 1e-4f * x) {
                log_warning(what + ": sigma " + std::to_string(sigma) +
                            " is not supported: radcache's Gaussian has sigma = radius / 3 = " +
                            std::to_string(x / 3.0f));
            }
        }
        camera_.filter.type = filter;
        camera_.filter.radius = x;
        params.warn_unused();
    }

    // The camera as radcache's, and the world mirror that keeps pbrt's image (pbrt_loader.h).
    void world_begin(const PbrtDirective& d) {
        const glm::dmat4 world_from_camera = glm::inverse(camera_from_world_);
        const glm::dvec3 eye(world_from_camera * glm::dvec4(0, 0, 0, 1));
        const glm::dmat3 axes(world_from_camera);
        const glm::dvec3 right = axes * glm::dvec3(1, 0, 0);
        const glm::dvec3 up = axes * glm::dvec3(0, 1, 0);
        const glm::dvec3 forward = axes * glm::dvec3(0, 0, 1);
        const double scale = glm::length(forward);
        const bool similar = std::isfinite(scale) && scale > 0.0 &&
                             std::abs(glm::length(right) - scale) <= 1e-4 * scale &&
                             std::abs(glm::length(up) - scale) <= 1e-4 * scale &&
                             std::abs(glm::dot(right, up)) <= 1e-4 * scale * scale &&
                             std::abs(glm::dot(right, forward)) <= 1e-4 * scale * scale &&
                             std::abs(glm::dot(up, forward)) <= 1e-4 * scale * scale &&
                             std::abs(world_from_camera[0][3]) + std::abs(world_from_camera[1][3]) +
                                     std::abs(world_from_camera[2][3]) ==
                                 0.0;
        if (!similar) {
            throw Error(d.where() +
                            ": the camera transform has shear, a projection or a "
                            "non-uniform scale, which radcache's camera cannot reproduce",
                        kExitUnsupported);
        }
        camera_.position = glm::vec3(eye);
        camera_.look_at = glm::vec3(eye + forward / scale);
        camera_.up = glm::vec3(up / scale);
        const glm::dvec3 ours = glm::cross(forward, up);  // radcache's image x (camera.h)
        if (glm::dot(ours, right) < 0.0) {
            const glm::dvec3 n = right / scale;
            const glm::dmat4 reflect = glm::dmat4(glm::dmat3(1.0) - 2.0 * glm::outerProduct(n, n));
            world_fix_ = glm::translate(glm::dmat4(1.0), eye) * reflect *
                         glm::translate(glm::dmat4(1.0), -eye);
        }
        in_world_ = true;
        attributes_.ctm = glm::dmat4(1.0);
        named_["world"] = glm::dmat4(1.0);
        scene_.base_camera = camera_;
        scene_.render.set("spp", spp_, spp_where_);
        scene_.render.set("max_depth", max_depth_, max_depth_where_);
        if (seed_) {
            scene_.render.set("seed", *seed_, spp_where_);
        }
    }

    void world_directive(const PbrtDirective& d) {
        // pbrt-v4 takes media before WorldBegin too (the camera's, through MediumInterface).
        if (d.name != "MakeNamedMedium" && d.name != "MediumInterface") {
            require(d, true);
        }
        if (d.name == "AttributeBegin") {
            stack_.push_back(attributes_);
            stack_.back().opened_at = d.where();
        } else if (d.name == "AttributeEnd") {
            if (stack_.empty() || stack_.back().saves_transform_only) {
                throw Error(d.where() + ": AttributeEnd without a matching AttributeBegin");
            }
            attributes_ = stack_.back();
            stack_.pop_back();
        } else if (d.name == "ReverseOrientation") {
            attributes_.reverse_orientation = !attributes_.reverse_orientation;
        } else if (d.name == "Material") {
            attributes_.material = materials_.define(d);
        } else if (d.name == "MakeNamedMaterial") {
            materials_.define_named(d);
        } else if (d.name == "NamedMaterial") {
            attributes_.material = materials_.named(d);
        } else if (d.name == "Texture") {
            materials_.define_texture(d);
        } else if (d.name == "Shape") {
            shape(d);
        } else if (d.name == "AreaLightSource") {
            area_light(d);
        } else if (d.name == "LightSource") {
            light_source(d);
        } else if (d.name == "ObjectBegin" || d.name == "ObjectEnd" || d.name == "ObjectInstance") {
            instancing(d);
        } else if (d.name == "MakeNamedMedium") {
            // A medium only matters where MediumInterface puts it.
        } else if (d.name == "MediumInterface") {
            for (const std::string& medium : d.strings) {
                if (!medium.empty()) {
                    throw Error(d.where() + ": MediumInterface " + in_quotes(medium) +
                                    ": participating media are not supported",
                                kExitUnsupported);
                }
            }
        } else if (d.name == "WorldEnd") {
            // pbrt-v3's end of the scene: nothing to do.
        } else {
            throw Error(d.where() + ": " + d.name + " is not supported", kExitUnsupported);
        }
    }

    void area_light(const PbrtDirective& d) {
        const std::string what = d.where() + ": AreaLightSource " + in_quotes(d.strings[0]);
        if (d.strings[0] != "diffuse") {
            throw Error(what + " is not supported (diffuse is)", kExitUnsupported);
        }
        PbrtParams params(d, what);
        if (params.has("filename") || params.has("power")) {
            params.refuse("\"filename\" and \"power\" are not supported: give \"rgb L\" and scale");
        }
        if (params.get_bool("twosided", false)) {
            params.refuse(
                "two-sided area lights are not supported (radcache's emit on the side "
                "of their normal)");
        }
        const glm::vec3 radiance =
            params.get_illuminant("L").value_or(glm::vec3(1.0f)) * params.get_float("scale", 1.0f);
        check_range(radiance, 1e9f, params, "L times scale");
        params.warn_unused();
        attributes_.area_radiance = radiance;
    }

    static void check_range(glm::vec3 value, float max, const PbrtParams& params,
                            const std::string& name) {
        for (int c = 0; c < 3; ++c) {
            if (!(value[c] >= 0.0f && value[c] <= max)) {
                params.fail(name + " component " + std::to_string(c) + " = " +
                            std::to_string(value[c]) + " outside [0, " + std::to_string(max) + "]");
            }
        }
    }

    glm::mat4 object_to_world(const PbrtDirective& d, const glm::dmat4& local) const {
        const glm::dmat4 m = world_fix_ * local;
        const double determinant = glm::determinant(glm::dmat3(m));
        if (!std::isfinite(determinant) || determinant == 0.0) {
            throw Error(d.where() + ": " + d.name + ": the current transform is not invertible");
        }
        return glm::mat4(m);
    }

    void shape(const PbrtDirective& d) {
        const std::string& type = d.strings[0];
        const std::string what = d.where() + ": Shape " + in_quotes(type);
        if (!is_pbrt_shape_supported(type)) {
            throw Error(what +
                            " is not supported (trianglemesh, plymesh, bilinearmesh, sphere, "
                            "disk, cylinder, loopsubdiv)",
                        kExitUnsupported);
        }
        PbrtParams params(d, what);
        Shape shape;
        shape.type = "pbrt";
        shape.mesh = pbrt_shape_mesh(type, params, dir_, files_);
        params.warn_unused();
        if (type == "sphere" || type == "disk" || type == "cylinder") {
            count_copied(shape.mesh.triangle_count(), d);
        }
        shape.flip_normals = attributes_.reverse_orientation;
        shape.materials.push_back(materials_.scene_material(attributes_.material));
        if (object_) {
            if (attributes_.area_radiance) {
                throw Error(what + ": area lights in object instances are not supported",
                            kExitUnsupported);
            }
            shape.transform = glm::mat4(attributes_.ctm);
            objects_[object_name_].push_back(std::move(shape));
            return;
        }
        shape.transform = object_to_world(d, attributes_.ctm);
        if (attributes_.area_radiance) {
            shape.emission.push_back(*attributes_.area_radiance);
            orient_to_normals(shape.mesh);
        }
        add_shape(std::move(shape));
    }

    void add_shape(Shape shape) {
        shape.name = "shape" + std::to_string(scene_.shapes.size());
        scene_.add_shape(std::move(shape));
    }

    void count_copied(size_t triangles, const PbrtDirective& d) {
        copied_triangles_ += triangles;
        if (copied_triangles_ > kMaxCopiedTriangles) {
            throw Error(d.where() + ": " + d.name +
                        ": instancing and tessellation make more than " +
                        std::to_string(kMaxCopiedTriangles) + " triangles");
        }
    }

    void instancing(const PbrtDirective& d) {
        if (d.name == "ObjectBegin") {
            if (object_) {
                throw Error(d.where() + ": ObjectBegin inside ObjectBegin " +
                            in_quotes(object_name_));
            }
            if (objects_.count(d.strings[0])) {
                throw Error(d.where() + ": ObjectBegin: an object named " +
                            in_quotes(d.strings[0]) + " is already defined");
            }
            stack_.push_back(attributes_);
            object_ = true;
            object_name_ = d.strings[0];
            objects_[object_name_];
        } else if (d.name == "ObjectEnd") {
            if (!object_ || stack_.empty() || stack_.back().saves_transform_only) {
                throw Error(d.where() + ": ObjectEnd without a matching ObjectBegin");
            }
            attributes_ = stack_.back();
            stack_.pop_back();
            object_ = false;
        } else {
            if (object_) {
                throw Error(d.where() + ": ObjectInstance inside an object definition");
            }
            const auto found = objects_.find(d.strings[0]);
            if (found == objects_.end()) {
                throw Error(d.where() + ": ObjectInstance: no object named " +
                            in_quotes(d.strings[0]));
            }
            for (const Shape& prototype : found->second) {
                count_copied(prototype.mesh.triangle_count(), d);
                Shape copy = prototype;
                copy.transform =
                    object_to_world(d, attributes_.ctm * glm::dmat4(prototype.transform));
                add_shape(std::move(copy));
            }
        }
    }

    // pbrt-v4's lights (Pharr et al., Physically Based Rendering, 4th ed., ch. 12; lights.cpp's
    // Create functions): RGB spectra times "scale", and the photometric "power" (point, spot)
    // and "illuminance" (distant, infinite) as pbrt-v4 normalises them for an RGB illuminant:
    // the emission times power / k_e, k_e the light's power at unit intensity.
    void light_source(const PbrtDirective& d) {
        const std::string& type = d.strings[0];
        const std::string what = d.where() + ": LightSource " + in_quotes(type);
        if (type != "point" && type != "spot" && type != "infinite" && type != "distant") {
            throw Error(what + " is not supported (point, spot, distant, infinite)",
                        kExitUnsupported);
        }
        PbrtParams params(d, what);
        if (params.has("filename") && type != "infinite") {
            params.refuse("image maps (\"filename\") are not supported here");
        }
        const float scale = params.get_float("scale", 1.0f);
        const glm::mat4 to_world = object_to_world(d, attributes_.ctm);
        Emitter emitter;
        emitter.name = "light" + std::to_string(scene_.emitters.size());
        if (type == "infinite") {
            infinite(params, to_world, scale, emitter);
        } else if (type == "distant") {
            distant(params, to_world, scale, emitter);
        } else {
            const glm::vec3 from = params.get_point3("from").value_or(glm::vec3(0.0f));
            emitter.position = transform_point(to_world, from);
            emitter.kind = type == "point" ? EmitterKind::kPoint : EmitterKind::kSpot;
            // k_e: 4 pi for a point light; a spot's set by spot().
            float unit_power = 4.0f * kPi;
            if (type == "spot") {
                unit_power = spot(params, to_world, from, emitter);
            }
            emitter.intensity = params.get_illuminant("I").value_or(glm::vec3(1.0f)) * scale *
                                photometric_factor(params, "power", unit_power);
            check_range(emitter.intensity, 1e12f, params, "I times scale");
        }
        params.warn_unused();
        scene_.emitters.push_back(emitter);
    }

    // The factor pbrt-v4 applies for a photometric parameter `name` (power or illuminance) given
    // as v > 0: v / k_e; 1 without it (pbrt's default of -1: any value <= 0 means none).
    static float photometric_factor(PbrtParams& params, const std::string& name, float k_e) {
        const float value = params.get_float(name, -1.0f);
        if (!std::isfinite(value)) {
            params.fail("\"" + name + "\" must be finite");
        }
        return value > 0.0f ? value / k_e : 1.0f;
    }

    // "infinite" without a map: the constant environment; illuminance E_v on an upward patch
    // under it is pi L (k_e = pi).
    void infinite(PbrtParams& params, const glm::mat4& to_world, float scale, Emitter& emitter) {
        params.ignore("portal");  // a sampling aid: the image is the same
        for (const Emitter& other : scene_.emitters) {
            if (other.kind == EmitterKind::kConstant) {
                params.refuse("a scene has at most one infinite light");
            }
        }
        emitter.kind = EmitterKind::kConstant;
        const std::string file = params.get_string("filename", "");
        if (!file.empty()) {
            image_infinite(params, to_world, scale, file, emitter);
            return;
        }
        emitter.radiance = params.get_illuminant("L").value_or(glm::vec3(1.0f)) * scale *
                           photometric_factor(params, "illuminance", kPi);
        check_range(emitter.radiance, 1e9f, params, "L times scale");
    }

    // "infinite" with "filename": pbrt-v4's ImageInfiniteLight, an equal-area octahedral map in
    // the light's frame (its CTM, with pbrt's mirrored x), times "scale".
    void image_infinite(PbrtParams& params, const glm::mat4& to_world, float scale,
                        const std::string& file, Emitter& emitter) {
        if (params.has("L")) {
            params.fail("\"L\" and \"filename\" together (pbrt-v4 refuses them too)");
        }
        if (params.has("illuminance")) {
            params.refuse("\"illuminance\" of an image map is not supported: give \"scale\"");
        }
        if (!(scale >= 0.0f && scale <= 1e9f)) {
            params.fail("scale must lie in [0, 1e9]");
        }
        glm::mat3 light_to_world(to_world);
        const float unit = std::cbrt(std::fabs(glm::determinant(light_to_world)));
        if (!(unit > 0.0f) || !std::isfinite(unit)) {
            params.fail("the light's transform collapses directions");
        }
        light_to_world /= unit;
        const glm::mat3 gram = glm::transpose(light_to_world) * light_to_world;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                if (std::fabs(gram[i][j] - (i == j ? 1.0f : 0.0f)) > 1e-3f) {
                    params.refuse(
                        "an image map under a transform that is not a rotation (with "
                        "a uniform scale)");
                }
            }
        }
        const std::filesystem::path path =
            std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : dir_ / file;
        if (!files_.exists(path)) {
            params.fail("image file \"" + excerpt(path.string()) + "\" not found");
        }
        try {
            load_environment_map(scene_, emitter, path, files_, glm::vec3(scale),
                                 RC_MAP_EQUAL_AREA);
        } catch (const Error& error) {
            params.fail(error.what());
        }
        emitter.map_from_world = glm::transpose(light_to_world);
    }

    // "distant": light travelling from "from" to "to" (default (0,0,0) to (0,0,1)), irradiance
    // L x scale on a surface facing it; "illuminance" is that irradiance (k_e = 1).
    void distant(PbrtParams& params, const glm::mat4& to_world, float scale, Emitter& emitter) {
        const glm::vec3 from = params.get_point3("from").value_or(glm::vec3(0.0f));
        const glm::vec3 to = params.get_point3("to").value_or(glm::vec3(0.0f, 0.0f, 1.0f));
        const glm::vec3 direction = glm::mat3(to_world) * (to - from);
        if (!(glm::length(direction) > 0.0f) || !std::isfinite(glm::length(direction))) {
            params.fail(
                "\"from\" and \"to\" give no direction (they coincide, or the "
                "transform collapses it)");
        }
        emitter.kind = EmitterKind::kDistant;
        emitter.direction = glm::normalize(direction);
        emitter.irradiance = params.get_illuminant("L").value_or(glm::vec3(1.0f)) * scale *
                             photometric_factor(params, "illuminance", 1.0f);
        check_range(emitter.irradiance, 1e9f, params, "L times scale");
    }

    // "spot": the cone and its axis; returns pbrt-v4's k_e for "power", the power of unit
    // intensity under its smoothstep falloff: 2 pi ((1 - cos start) + (cos start - cos end) / 2).
    float spot(PbrtParams& params, const glm::mat4& to_world, glm::vec3 from, Emitter& emitter) {
        const glm::vec3 to = params.get_point3("to").value_or(glm::vec3(0, 0, 1));
        if (!(glm::length(to - from) > 0.0f)) {
            params.fail("\"from\" and \"to\" coincide");
        }
        emitter.look_at = transform_point(to_world, to);
        const float cone = params.get_float("coneangle", 30.0f);
        const float delta = params.get_float("conedeltaangle", 5.0f);
        if (!(cone > 0.0f && cone < 90.0f)) {
            params.fail("coneangle must lie in (0, 90) degrees");
        }
        if (!(delta >= 0.0f && delta <= cone)) {
            params.fail("conedeltaangle must lie in [0, coneangle]");
        }
        emitter.cutoff_angle = cone;
        emitter.beam_width = std::clamp(cone - delta, 1e-3f, 0.999f * cone);
        if (!warned_spot_) {
            log_warning(params.what() +
                        ": radcache's spot falls off linearly in angle between coneangle - "
                        "conedeltaangle and coneangle, pbrt's smoothly in cosine");
            warned_spot_ = true;
        }
        const float cos_end = std::cos(glm::radians(cone));
        const float cos_start = std::cos(glm::radians(cone - delta));
        return 2.0f * kPi * ((1.0f - cos_start) + 0.5f * (cos_start - cos_end));
    }

    std::string file_;
    std::filesystem::path dir_;
    const SceneFiles& files_;
    Scene& scene_;
    PbrtMaterials materials_;
    Attributes attributes_;
    std::vector<Attributes> stack_;
    std::map<std::string, glm::dmat4> named_;
    glm::dmat4 camera_from_world_{1.0};
    glm::dmat4 world_fix_{1.0};
    Camera camera_{.fov_degrees = 90.0f,
                   .fov_axis = FovAxis::kSmaller,
                   .width = 1280,
                   .height = 720,
                   .filter = {RC_FILTER_GAUSSIAN, 1.5f}};
    long long spp_ = 16;
    std::string spp_where_ = "pbrt's default Sampler";
    int max_depth_ = 5;
    std::string max_depth_where_ = "pbrt's default Integrator";
    std::optional<int> seed_;
    bool in_world_ = false;
    bool object_ = false;
    std::string object_name_;
    std::map<std::string, std::vector<Shape>> objects_;
    size_t copied_triangles_ = 0;
    bool warned_spot_ = false;
};

}  // namespace

Scene load_pbrt_scene(const std::filesystem::path& path, const SceneFiles& files) {
    const std::vector<PbrtDirective> directives = parse_pbrt_file(path, files);
    return imported_scene(
        path, [&](Scene& scene) { PbrtSceneBuilder(path, files, scene).build(directives); });
}

}  // namespace rc
