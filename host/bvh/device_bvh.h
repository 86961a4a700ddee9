// A BVH uploaded to a device: the buffers the traversal kernels read.
#pragma once

#include "bvh/bvh.h"
#include "device/buffer.h"
#include "shared/types.h"

namespace rc {

class Context;

struct DeviceBvh {
    DeviceBvh(Context& context, const Bvh& bvh);

    Buffer<shared::BvhNode> nodes;
    Buffer<shared::Triangle> triangles;
    Buffer<unsigned> triangle_of_primitive;
};

}  // namespace rc
