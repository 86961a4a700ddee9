// The L-tree of an SDRC record on the host (SDRC §4.3; DESIGN.md §6.5): its radiance samples
// (kernels/shared/sdrc.h LTreeNode) arranged as a kd-tree in median order, which the device's
// range query (kernels/sdrc/ltree.h) walks, and the records' trees packed into one node array.
#pragma once

#include <cstddef>
#include <vector>

#include "shared/sdrc.h"

namespace rc {

// Arranges `nodes` as a kd-tree in median order: the node of a range [lo, hi) at
// lo + (hi - lo) / 2, the range split along the axis (u or v) of its larger extent, nodes at or
// below the median's coordinate before it and at or above after it; the axis into the median's
// bookkeeping bits. Empty nodes (RC_LTREE_EMPTY) are dropped first. Deterministic: ties are
// broken by the whole node.
void build_ltree(std::vector<shared::LTreeNode>* nodes);

// One record's samples: a kd-tree and the buffer of samples inserted since it was built.
struct LTree {
    std::vector<shared::LTreeNode> tree;
    std::vector<shared::LTreeNode> buffer;
    size_t rebuilds = 0;

    size_t size() const { return tree.size() + buffer.size(); }
    // Appends a sample to the buffer; when the buffer holds `buffer_capacity` samples, rebuilds
    // the tree over all of them (SDRC §4.4).
    void insert(shared::LTreeNode node, size_t buffer_capacity);
};

// The records' L-trees as the kernels read them: nodes record after record (tree, then buffer)
// and each record's SdrcTree.
struct PackedLTrees {
    std::vector<shared::LTreeNode> nodes;
    std::vector<shared::SdrcTree> trees;
};
PackedLTrees pack_ltrees(const std::vector<LTree>& trees);

}  // namespace rc
