#include "methods/normals/normals.h"

#include "image/film.h"
#include "scene/camera.h"
#include "util/error.h"

namespace rc {

NormalsMethod::NormalsMethod(const FrameScene& frame)
    : FrameBound(frame), kernel_(frame.context.kernel("normals/normals.cl", "render_normals")) {}

Image NormalsMethod::render(const NormalsOptions& options) {
    const int width = options.width > 0 ? options.width : scene_.camera.width;
    const int height = options.height > 0 ? options.height : scene_.camera.height;
    if (options.samples_per_pixel == 0) {
        throw Error("samples per pixel must be at least 1", kExitUsage);
    }
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    const shared::CameraParams camera = camera_params(scene_.camera, width, height);
    Buffer<shared::float4> film(context_, pixels, "film");
    const auto seed_lo = static_cast<unsigned>(options.seed);
    const auto seed_hi = static_cast<unsigned>(options.seed >> 32);
    context_.launch(kernel_, pixels, camera, bvh_.nodes, bvh_.triangles, bvh_.triangle_of_primitive,
                    options.samples_per_pixel, seed_lo, seed_hi, film);
    return unpack_film(film.download(), 1, width, height, {{"beauty", 0}});
}

}  // namespace rc
