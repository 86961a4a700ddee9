// The compressed 8-wide layout (docs/bvh.md): Embree's 8-wide tree with each node's child boxes
// quantised to bytes on a per-node grid (Ylitie, Karras and Laine 2017, §3.1), the children that
// are inner nodes stored next to each other, and the node's leaves as packets of four triangles
// next to each other.
#include <algorithm>
#include <cmath>
#include <limits>

#include "bvh/bvh_flatten.h"
#include "util/error.h"

namespace rc {
namespace {

constexpr unsigned kWidth = RC_WIDE_BVH_WIDTH;
constexpr int kMinExponent = -126;  // the scale 2^e stays a normal float
constexpr int kMaxExponent = 127;

// One axis of a node's grid: planes origin + q * 2^exponent, q in [0, 255], evaluated in float
// exactly as the kernel does (q * 2^e is exact, so one rounding whether fused or not).
struct AxisGrid {
    float origin;
    int exponent;

    float plane(int q) const { return origin + static_cast<float>(q) * std::ldexp(1.0f, exponent); }
    // The largest q whose plane is at or below `lower`.
    uint8_t quantise_lower(float lower) const {
        int q =
            std::clamp(static_cast<int>(std::floor(std::ldexp(lower - origin, -exponent))), 0, 255);
        while (q > 0 && plane(q) > lower) {
            --q;
        }
        while (q < 255 && plane(q + 1) <= lower) {
            ++q;
        }
        return static_cast<uint8_t>(q);
    }
    // The smallest q whose plane is at or above `upper`.
    uint8_t quantise_upper(float upper) const {
        int q =
            std::clamp(static_cast<int>(std::ceil(std::ldexp(upper - origin, -exponent))), 0, 255);
        while (q < 255 && plane(q) < upper) {
            ++q;
        }
        while (q > 0 && plane(q - 1) >= upper) {
            --q;
        }
        return static_cast<uint8_t>(q);
    }
};

// The finest grid from `lower` whose last plane (q = 255) reaches `upper`.
AxisGrid axis_grid(float lower, float upper) {
    AxisGrid grid{lower, kMinExponent};
    const double extent = static_cast<double>(upper) - static_cast<double>(lower);
    if (extent > 0.0) {
        int exponent = 0;
        std::frexp(extent / 255.0, &exponent);  // extent / 255 < 2^exponent
        grid.exponent = std::clamp(exponent - 1, kMinExponent, kMaxExponent);
    }
    while (grid.exponent < kMaxExponent && grid.plane(255) < upper) {
        ++grid.exponent;
    }
    return grid;
}

uint8_t biased(int exponent) { return static_cast<uint8_t>(exponent + 127); }

// Quantises the child boxes; every child's box on the grid holds its float box.
void quantise_children(const InnerBuildNode& build, shared::WideBvhNode& node) {
    RTCBounds box = build.bounds[0];
    for (unsigned i = 1; i < build.child_count; ++i) {
        grow_bounds(box, build.bounds[i]);
    }
    const AxisGrid x = axis_grid(box.lower_x, box.upper_x);
    const AxisGrid y = axis_grid(box.lower_y, box.upper_y);
    const AxisGrid z = axis_grid(box.lower_z, box.upper_z);
    node.origin_x = x.origin;
    node.origin_y = y.origin;
    node.origin_z = z.origin;
    node.exponent_x = biased(x.exponent);
    node.exponent_y = biased(y.exponent);
    node.exponent_z = biased(z.exponent);
    for (unsigned i = 0; i < build.child_count; ++i) {
        const RTCBounds& b = build.bounds[i];
        node.lower_x[i] = x.quantise_lower(b.lower_x);
        node.upper_x[i] = x.quantise_upper(b.upper_x);
        node.lower_y[i] = y.quantise_lower(b.lower_y);
        node.upper_y[i] = y.quantise_upper(b.upper_y);
        node.lower_z[i] = z.quantise_lower(b.lower_z);
        node.upper_z[i] = z.quantise_upper(b.upper_z);
    }
}

// Triangles [first, first + 4) of the leaf by axis; lanes past the leaf's end repeat its
// triangle `first`.
shared::TrianglePacket triangle_packet(const LeafBuildNode& leaf, unsigned first,
                                       const TriangleMesh& mesh) {
    shared::TrianglePacket packet{};
    for (unsigned lane = 0; lane < 4; ++lane) {
        const unsigned primitive =
            leaf.primitives[first + lane < leaf.count ? first + lane : first];
        const glm::uvec3& t = mesh.triangles[primitive];
        for (int axis = 0; axis < 3; ++axis) {
            (&packet.v0[axis].x)[lane] = mesh.positions[t.x][axis];
            (&packet.v1[axis].x)[lane] = mesh.positions[t.y][axis];
            (&packet.v2[axis].x)[lane] = mesh.positions[t.z][axis];
        }
        (&packet.primitive.x)[lane] = primitive;
    }
    return packet;
}

class WideFlattener {
   public:
    WideFlattener(const TriangleMesh& mesh, Bvh& bvh) : mesh_(mesh), bvh_(bvh) {}

    // Fills node `index` from `build`, places its inner children next to each other at the end
    // of the node array and its leaves' packets next to each other at the end of the packets,
    // then flattens the inner children.
    void flatten(const InnerBuildNode& build, size_t index, unsigned depth) {
        if (build.child_count > kWidth) {
            throw Error("the wide BVH got a node of " + std::to_string(build.child_count) +
                        " children");
        }
        bvh_.depth = std::max(bvh_.depth, depth);
        // Inner children take the first slots, leaves the next ones.
        InnerBuildNode sorted = build;
        unsigned slot = 0;
        for (bool leaves : {false, true}) {
            for (unsigned i = 0; i < build.child_count; ++i) {
                if (build.children[i]->is_leaf == leaves) {
                    sorted.children[slot] = build.children[i];
                    sorted.bounds[slot] = build.bounds[i];
                    ++slot;
                }
            }
        }
        shared::WideBvhNode node = empty_wide_node();
        quantise_children(sorted, node);
        node.child_base = static_cast<uint32_t>(bvh_.wide_nodes.size());
        node.packet_base = static_cast<uint32_t>(bvh_.packets.size());
        unsigned inner_count = 0;
        for (unsigned i = 0; i < sorted.child_count; ++i) {
            const BuildNode* child = sorted.children[i];
            if (child->is_leaf) {
                const auto& leaf = *static_cast<const LeafBuildNode*>(child);
                append_leaf_triangles(leaf, mesh_, bvh_);
                const unsigned packet_count = (leaf.count + 3) / 4;
                node.meta[i] = static_cast<uint8_t>((packet_count << 5) |
                                                    (bvh_.packets.size() - node.packet_base));
                for (unsigned first = 0; first < leaf.count; first += 4) {
                    bvh_.packets.push_back(triangle_packet(leaf, first, mesh_));
                }
            } else {
                node.inner_mask = static_cast<uint8_t>(node.inner_mask | (1u << i));
                ++inner_count;
            }
        }
        bvh_.wide_nodes.resize(bvh_.wide_nodes.size() + inner_count);
        bvh_.wide_nodes[index] = node;
        for (unsigned i = 0; i < inner_count; ++i) {
            flatten(*static_cast<const InnerBuildNode*>(sorted.children[i]), node.child_base + i,
                    depth + 1);
        }
    }

   private:
    const TriangleMesh& mesh_;
    Bvh& bvh_;
};

}  // namespace

shared::WideBvhNode empty_wide_node() {
    shared::WideBvhNode node{};
    node.exponent_x = node.exponent_y = node.exponent_z = biased(0);
    for (unsigned i = 0; i < kWidth; ++i) {
        node.lower_x[i] = node.lower_y[i] = node.lower_z[i] = 255;
        node.upper_x[i] = node.upper_y[i] = node.upper_z[i] = 0;
    }
    return node;
}

void flatten_wide(const BuildNode& root, const TriangleMesh& mesh, Bvh& bvh) {
    bvh.wide_nodes.push_back(empty_wide_node());
    if (!root.is_leaf) {
        WideFlattener(mesh, bvh).flatten(static_cast<const InnerBuildNode&>(root), 0, 1);
    } else {
        // A tree that is one leaf: a root with that leaf as its only child.
        const auto& leaf = static_cast<const LeafBuildNode&>(root);
        InnerBuildNode only{};
        only.is_leaf = false;
        only.child_count = 1;
        only.children[0] = &leaf;
        only.bounds[0] = leaf_bounds(leaf, mesh);
        WideFlattener(mesh, bvh).flatten(only, 0, 1);
    }
    // The packets follow the nodes in the device's node buffer: count them from its start.
    const size_t packet_offset = bvh.wide_packet_offset();
    if (packet_offset + bvh.packets.size() > std::numeric_limits<uint32_t>::max()) {
        throw Error("too many leaf packets for the wide BVH: " +
                    std::to_string(bvh.packets.size()));
    }
    for (shared::WideBvhNode& node : bvh.wide_nodes) {
        node.packet_base += static_cast<uint32_t>(packet_offset);
    }
}

}  // namespace rc
