#include "methods/scene_arguments.h"

namespace rc {
namespace {

void set_buffer(Kernel& kernel, unsigned index, const DeviceBuffer& buffer) {
    _cl_mem* handle = buffer.handle();
    kernel.set_arg(index, sizeof handle, &handle);
}

}  // namespace

unsigned SceneArguments::set_kernel_args(Kernel& kernel, unsigned first) const {
    const DeviceBuffer* buffers[] = {&bvh_.nodes,
                                     &bvh_.triangles,
                                     &bvh_.triangle_of_primitive,
                                     &scene_.shading,
                                     &scene_.normals,
                                     &scene_.uvs,
                                     &scene_.materials,
                                     &scene_.textures,
                                     &scene_.texels,
                                     &scene_.lights,
                                     &scene_.light_cdf,
                                     &scene_.light_triangles,
                                     &scene_.light_triangle_cdf};
    unsigned index = first;
    for (const DeviceBuffer* buffer : buffers) {
        set_buffer(kernel, index++, *buffer);
    }
    kernel.set_arg(index++, sizeof scene_.light_count, &scene_.light_count);
    kernel.set_arg(index++, sizeof scene_.environment, &scene_.environment);
    return index - first;
}

}  // namespace rc
