#include "bvh/device_bvh.h"

#include "device/context.h"
#include "util/error.h"

namespace rc {
namespace {

DeviceBuffer upload_nodes(Context& context, const Bvh& bvh) {
    if (bvh.layout != context.bvh_layout()) {
        throw Error(std::string("a BVH in the ") + bvh_layout_name(bvh.layout) +
                    " layout given to programs built for the " +
                    bvh_layout_name(context.bvh_layout()) + " layout");
    }
    if (bvh.layout != BvhLayout::kWide) {
        DeviceBuffer nodes(context, bvh.node_bytes(), "bvh_nodes");
        nodes.write(bvh.nodes.data(), bvh.node_bytes());
        return nodes;
    }
    // The wide nodes, then the leaf packets from packet index wide_packet_offset() on.
    const size_t packets_at = bvh.wide_packet_offset() * sizeof(shared::TrianglePacket);
    DeviceBuffer nodes(context, packets_at + bvh.leaf_bytes(), "bvh_nodes");
    nodes.write(bvh.wide_nodes.data(), bvh.node_bytes());
    nodes.write(bvh.packets.data(), bvh.leaf_bytes(), packets_at);
    return nodes;
}

}  // namespace

DeviceBvh::DeviceBvh(Context& context, const Bvh& bvh)
    : nodes(upload_nodes(context, bvh)),
      triangles(context, bvh.triangles, "bvh_triangles"),
      triangle_of_primitive(context, bvh.triangle_of_primitive, "triangle_of_primitive") {}

}  // namespace rc
