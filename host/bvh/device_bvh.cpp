#include "bvh/device_bvh.h"

#include <algorithm>

#include "device/context.h"
#include "device/memory_need.h"
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

uint64_t DeviceBvh::bytes_for(const Bvh& bvh) {
    const uint64_t nodes =
        bvh.layout != BvhLayout::kWide
            ? bvh.node_bytes()
            : bvh.wide_packet_offset() * sizeof(shared::TrianglePacket) + bvh.leaf_bytes();
    return std::max<uint64_t>(nodes, 1) +
           buffer_bytes(bvh.triangles.size(), sizeof(shared::Triangle)) +
           buffer_bytes(bvh.triangle_of_primitive.size(), sizeof(unsigned));
}

}  // namespace rc
