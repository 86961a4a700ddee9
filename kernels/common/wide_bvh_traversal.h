// Closest-hit and any-hit traversal of the compressed 8-wide BVH (WideBvhNode, docs/bvh.md). A
// node's eight child boxes are decoded and tested at once as float8 lanes (SIMD on PoCL), and a
// leaf's triangles four at a time (TrianglePacket). At each node both traversals test the hit
// leaves at once; the closest-hit traversal then visits the hit inner children near to far with
// a private stack of (child, entry distance), the any-hit traversal in slot order.
#pragma once

#include "common/bvh_ray.h"
#include "shared/types.h"

// The ray's distances to one axis's planes of the eight children: origin + q * 2^(exponent -
// 127), exact as built (the eight bytes read as one 8-byte word: they are 8-byte aligned in the
// node), minus the ray's origin, times its inverse direction.
RC_FUNC float8 rc_wide_slab(RC_GLOBAL const uchar* q, float origin, uchar exponent,
                            float ray_origin, float inv_direction) {
    const float scale = rc_as_float((uint)exponent << 23);
    const float8 planes = convert_float8(as_uchar8(*(RC_GLOBAL const ulong*)q)) * scale + origin;
    return (planes - ray_origin) * inv_direction;
}

// The entry distance of the ray into each child box over [tmin, tmax]; returns the children
// whose box is hit as bits. Entry and exit planes are chosen by the sign of the direction as in
// the 4-wide test (bvh4_traversal.h), with the same robust far scale.
RC_FUNC uint rc_intersect_wide_node(RC_GLOBAL const WideBvhNode* node, const BoxRay* r, float tmin,
                                    float tmax, float* t_enter) {
    const float3 o = r->origin;
    const float3 inv = r->inv_direction;
    const float8 near_x = rc_wide_slab(r->negative_x ? node->upper_x : node->lower_x,
                                       node->origin_x, node->exponent_x, o.x, inv.x);
    const float8 far_x = rc_wide_slab(r->negative_x ? node->lower_x : node->upper_x, node->origin_x,
                                      node->exponent_x, o.x, inv.x);
    const float8 near_y = rc_wide_slab(r->negative_y ? node->upper_y : node->lower_y,
                                       node->origin_y, node->exponent_y, o.y, inv.y);
    const float8 far_y = rc_wide_slab(r->negative_y ? node->lower_y : node->upper_y, node->origin_y,
                                      node->exponent_y, o.y, inv.y);
    const float8 near_z = rc_wide_slab(r->negative_z ? node->upper_z : node->lower_z,
                                       node->origin_z, node->exponent_z, o.z, inv.z);
    const float8 far_z = rc_wide_slab(r->negative_z ? node->lower_z : node->upper_z, node->origin_z,
                                      node->exponent_z, o.z, inv.z);
    // A 0 * inf = NaN slab (ray in a box plane) drops out: each comparison below keeps the
    // running bound when the slab is NaN.
    float8 near_t = (float8)(tmin);
    near_t = near_x > near_t ? near_x : near_t;
    near_t = near_y > near_t ? near_y : near_t;
    near_t = near_z > near_t ? near_z : near_t;
    float8 far_t = (float8)(tmax);
    far_t = far_x < far_t ? far_x : far_t;
    far_t = far_y < far_t ? far_y : far_t;
    far_t = far_z < far_t ? far_z : far_t;
    vstore8(near_t, 0, t_enter);
    // Lane i's 0/1 in byte i of a word; the multiplication gathers the eight bits in its top
    // byte.
    const ulong bytes = as_ulong(convert_uchar8(near_t <= far_t * RC_BOX_FAR_SCALE) & (uchar8)(1));
    return (uint)((bytes * 0x0102040810204080ul) >> 56);
}

// Index of the lowest set bit (mask != 0).
RC_FUNC uint rc_lowest_bit(uint mask) { return 31u - clz(mask & (0u - mask)); }

// Tests the triangle packet against the ray's own interval and keeps the nearest hit in *hit
// (rc_is_nearer_hit); returns whether it kept one. With any_hit set, keeps any hit.
RC_FUNC bool rc_intersect_packet(RC_GLOBAL const TrianglePacket* packet, const TraversalRay* ray,
                                 bool any_hit, Hit* hit) {
    float4 t, u, v;
    const int4 lanes =
        rc_intersect_triangle_packet(&ray->watertight, packet, ray->tmin, ray->tmax, &t, &u, &v);
    if (!any(lanes)) {
        return false;
    }
    const uint4 primitive = packet->primitive;
    bool found = false;
#define RC_KEEP_LANE(lane)                                                          \
    if (lanes.lane && (any_hit || rc_is_nearer_hit(t.lane, primitive.lane, hit))) { \
        hit->t = t.lane;                                                            \
        hit->u = u.lane;                                                            \
        hit->v = v.lane;                                                            \
        hit->primitive = primitive.lane;                                            \
        found = true;                                                               \
    }
    RC_KEEP_LANE(x)
    RC_KEEP_LANE(y)
    RC_KEEP_LANE(z)
    RC_KEEP_LANE(w)
#undef RC_KEEP_LANE
    return found;
}

// Tests the node's leaves among `hits` (bits of child slots); with any_hit set, returns at the
// first hit.
RC_FUNC bool rc_intersect_wide_leaves(RC_GLOBAL const WideBvhNode* node,
                                      RC_GLOBAL const TrianglePacket* packets, uint hits,
                                      const TraversalRay* ray, bool any_hit, Hit* hit) {
    uint leaves = hits & ~(uint)node->inner_mask;
    bool found = false;
    while (leaves != 0u) {
        const uint slot = rc_lowest_bit(leaves);
        leaves &= leaves - 1u;
        const uint meta = node->meta[slot];
        RC_GLOBAL const TrianglePacket* packet = packets + node->packet_base + (meta & 31u);
        for (uint i = 0; i < meta >> 5; ++i) {
            if (rc_intersect_packet(packet + i, ray, any_hit, hit)) {
                found = true;
                if (any_hit) {
                    return true;
                }
            }
        }
    }
    return found;
}

// Closest hit: at each node the hit leaves are tested at once and the hit inner children pushed
// sorted far to near, so that the nearest is popped next; popped entries farther than the
// closest hit so far are skipped.
RC_FUNC void rc_traverse_wide_closest(RC_GLOBAL const WideBvhNode* nodes, const TraversalRay* ray,
                                      Hit* hit) {
    RC_GLOBAL const TrianglePacket* packets = (RC_GLOBAL const TrianglePacket*)nodes;
    uint stack_node[RC_WIDE_BVH_STACK_SIZE];
    float stack_t[RC_WIDE_BVH_STACK_SIZE];
    int stack_size = 0;
    uint node_index = 0;  // the root
    for (;;) {
        RC_GLOBAL const WideBvhNode* node = nodes + node_index;
        float t_enter[RC_WIDE_BVH_WIDTH];
        const uint hits = rc_intersect_wide_node(node, &ray->box, ray->tmin, hit->t, t_enter);
        rc_intersect_wide_leaves(node, packets, hits, ray, false, hit);
        uint inner = hits & node->inner_mask;
        const int first = stack_size;
        while (inner != 0u) {
            const uint slot = rc_lowest_bit(inner);
            inner &= inner - 1u;
            const float t = t_enter[slot];
            int j = stack_size++;
            while (j > first && stack_t[j - 1] < t) {
                stack_t[j] = stack_t[j - 1];
                stack_node[j] = stack_node[j - 1];
                --j;
            }
            stack_t[j] = t;
            stack_node[j] = node->child_base + slot;
        }
        for (;;) {
            if (stack_size == 0) {
                return;
            }
            --stack_size;
            if (rc_may_hold_nearer_hit(stack_t[stack_size], hit)) {
                break;
            }
        }
        node_index = stack_node[stack_size];
    }
}

// Any hit: the node's hit leaves are tested at once, its hit inner children pushed in slot order.
RC_FUNC bool rc_traverse_wide_any(RC_GLOBAL const WideBvhNode* nodes, const TraversalRay* ray,
                                  Hit* hit) {
    RC_GLOBAL const TrianglePacket* packets = (RC_GLOBAL const TrianglePacket*)nodes;
    uint stack[RC_WIDE_BVH_STACK_SIZE];
    int stack_size = 0;
    uint node_index = 0;  // the root
    for (;;) {
        RC_GLOBAL const WideBvhNode* node = nodes + node_index;
        float t_enter[RC_WIDE_BVH_WIDTH];
        const uint hits = rc_intersect_wide_node(node, &ray->box, ray->tmin, ray->tmax, t_enter);
        if (rc_intersect_wide_leaves(node, packets, hits, ray, true, hit)) {
            return true;
        }
        uint inner = hits & node->inner_mask;
        while (inner != 0u) {
            const uint slot = rc_lowest_bit(inner);
            inner &= inner - 1u;
            stack[stack_size++] = node->child_base + slot;
        }
        if (stack_size == 0) {
            return false;
        }
        node_index = stack[--stack_size];
    }
}
