#include "bvh/device_bvh.h"

#include "device/context.h"

namespace rc {

DeviceBvh::DeviceBvh(Context& context, const Bvh& bvh)
    : nodes(context, bvh.nodes, "bvh_nodes"),
      triangles(context, bvh.triangles, "bvh_triangles"),
      triangle_of_primitive(context, bvh.triangle_of_primitive, "triangle_of_primitive") {}

}  // namespace rc
