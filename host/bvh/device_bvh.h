// A BVH uploaded to a device: the buffers the traversal kernels read.
#pragma once

#include "bvh/bvh.h"
#include "device/buffer.h"
#include "shared/types.h"

namespace rc {

class Context;

struct DeviceBvh {
    // The BVH must be in the layout the context's programs are built for (Context::bvh_layout).
    DeviceBvh(Context& context, const Bvh& bvh);
    // What the constructor allocates for `bvh`, before it does.
    static uint64_t bytes_for(const Bvh& bvh);

    DeviceBuffer nodes;  // BvhNode or WideBvhNode records, by the layout
    Buffer<shared::Triangle> triangles;
    Buffer<unsigned> triangle_of_primitive;
};

}  // namespace rc
