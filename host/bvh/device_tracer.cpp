#include "bvh/device_tracer.h"

namespace rc {

DeviceTracer::DeviceTracer(Context& context, const DeviceBvh& bvh)
    : context_(context),
      bvh_(bvh),
      closest_(context.kernel("trace.cl", "trace_closest")),
      any_(context.kernel("trace.cl", "trace_any")),
      camera_(context.kernel("spawn_rays.cl", "spawn_camera_rays")),
      bounce_(context.kernel("spawn_rays.cl", "spawn_diffuse_rays")) {}

void DeviceTracer::trace_closest(const Buffer<shared::Ray>& rays, Buffer<shared::Hit>& hits) {
    context_.launch(closest_, rays.size(), rays, bvh_.nodes, bvh_.triangles, hits);
}

void DeviceTracer::trace_any(const Buffer<shared::Ray>& rays, Buffer<unsigned>& occluded) {
    context_.launch(any_, rays.size(), rays, bvh_.nodes, bvh_.triangles, occluded);
}

std::vector<shared::Hit> DeviceTracer::trace_closest(const std::vector<shared::Ray>& rays) {
    const Buffer<shared::Ray> ray_buffer(context_, rays, "rays");
    Buffer<shared::Hit> hits(context_, rays.size(), "hits");
    trace_closest(ray_buffer, hits);
    return hits.download();
}

std::vector<unsigned> DeviceTracer::trace_any(const std::vector<shared::Ray>& rays) {
    const Buffer<shared::Ray> ray_buffer(context_, rays, "rays");
    Buffer<unsigned> occluded(context_, rays.size(), "occluded");
    trace_any(ray_buffer, occluded);
    return occluded.download();
}

std::vector<shared::Ray> DeviceTracer::camera_rays(const shared::CameraParams& camera) {
    const size_t count =
        static_cast<size_t>(camera.resolution.x) * static_cast<size_t>(camera.resolution.y);
    Buffer<shared::Ray> rays(context_, count, "camera_rays");
    context_.launch(camera_, count, camera, rays);
    return rays.download();
}

std::vector<shared::Ray> DeviceTracer::diffuse_bounce_rays(const std::vector<shared::Ray>& rays,
                                                           uint64_t seed, bool traceable_only) {
    const Buffer<shared::Ray> ray_buffer(context_, rays, "rays");
    Buffer<shared::Hit> hits(context_, rays.size(), "hits");
    trace_closest(ray_buffer, hits);
    Buffer<shared::Ray> bounces(context_, rays.size(), "bounce_rays");
    context_.launch(bounce_, rays.size(), ray_buffer, hits, bvh_.triangles,
                    bvh_.triangle_of_primitive, static_cast<unsigned>(seed),
                    static_cast<unsigned>(seed >> 32), bounces);
    std::vector<shared::Ray> result = bounces.download();
    if (traceable_only) {
        std::erase_if(result, [](const shared::Ray& r) {
            return r.direction.x == 0.0f && r.direction.y == 0.0f && r.direction.z == 0.0f;
        });
    }
    return result;
}

}  // namespace rc
