#include "methods/sdrc/ltree.h"

#include <algorithm>
#include <tuple>

#include "util/error.h"

namespace rc {
namespace {

using shared::LTreeNode;

uint32_t coordinate(const LTreeNode& node, int axis) {
    return axis == 0 ? shared::rc_ltree_node_u(node.position)
                     : shared::rc_ltree_node_v(node.position);
}

// The 16 position bits, with the bookkeeping bits cleared.
uint32_t cell_bits(const LTreeNode& node) { return node.position & 0xffffu; }

// The axis of the larger extent of nodes [lo, hi) (u on a tie).
int split_axis(const LTreeNode* lo, const LTreeNode* hi) {
    uint32_t min[2] = {255, 255};
    uint32_t max[2] = {0, 0};
    for (const LTreeNode* n = lo; n != hi; ++n) {
        for (int axis = 0; axis < 2; ++axis) {
            min[axis] = std::min(min[axis], coordinate(*n, axis));
            max[axis] = std::max(max[axis], coordinate(*n, axis));
        }
    }
    return max[1] - min[1] > max[0] - min[0] ? 1 : 0;
}

void build_range(LTreeNode* lo, LTreeNode* hi) {
    while (hi - lo > 1) {
        const int axis = split_axis(lo, hi);
        LTreeNode* mid = lo + (hi - lo) / 2;
        std::nth_element(lo, mid, hi, [axis](const LTreeNode& a, const LTreeNode& b) {
            return std::make_tuple(coordinate(a, axis), coordinate(a, 1 - axis), a.radiance) <
                   std::make_tuple(coordinate(b, axis), coordinate(b, 1 - axis), b.radiance);
        });
        mid->position = cell_bits(*mid) | static_cast<uint32_t>(axis) << RC_LTREE_AXIS_SHIFT;
        build_range(lo, mid);
        lo = mid + 1;  // the upper half in the loop: recursion depth stays log2(size)
    }
    if (hi - lo == 1) {
        lo->position = cell_bits(*lo);
    }
}

}  // namespace

void build_ltree(std::vector<LTreeNode>* nodes) {
    nodes->erase(
        std::remove_if(nodes->begin(), nodes->end(),
                       [](const LTreeNode& n) { return (n.position & RC_LTREE_EMPTY) != 0; }),
        nodes->end());
    if (nodes->size() > RC_LTREE_MAX_NODES) {
        throw Error("an SDRC L-tree would hold " + std::to_string(nodes->size()) +
                    " samples, more than " + std::to_string(RC_LTREE_MAX_NODES));
    }
    build_range(nodes->data(), nodes->data() + nodes->size());
}

void LTree::insert(LTreeNode node, size_t buffer_capacity) {
    buffer.push_back(node);
    if (buffer.size() >= buffer_capacity) {
        tree.insert(tree.end(), buffer.begin(), buffer.end());
        buffer.clear();
        build_ltree(&tree);
        ++rebuilds;
    }
}

PackedLTrees pack_ltrees(const std::vector<LTree>& trees) {
    PackedLTrees packed;
    size_t total = 0;
    for (const LTree& t : trees) {
        total += t.size();
    }
    packed.nodes.reserve(total);
    packed.trees.reserve(trees.size());
    for (const LTree& t : trees) {
        shared::SdrcTree entry{};
        entry.first_node = static_cast<uint32_t>(packed.nodes.size());
        entry.tree_nodes = static_cast<uint32_t>(t.tree.size());
        entry.buffer_nodes = static_cast<uint32_t>(t.buffer.size());
        packed.nodes.insert(packed.nodes.end(), t.tree.begin(), t.tree.end());
        packed.nodes.insert(packed.nodes.end(), t.buffer.begin(), t.buffer.end());
        packed.trees.push_back(entry);
    }
    return packed;
}

}  // namespace rc
