// The grid that finds a shading point's near triangles (Arikan, Forsyth and O'Brien 2005, §5;
// the kernels' NearField, kernels/decomposition/decomp_near.h): one record per split triangle
// about its centroid, with the reach its near-set rule needs.
#pragma once

#include <vector>

#include "methods/caching/record_grid.h"
#include "shared/decomposition.h"

namespace rc {

// The record grid over the split triangles' centroids: reach alpha with RC_DECOMP_NEAR_CENTROID
// (a triangle whose centroid lies within alpha of p), alpha plus the farthest vertex's distance
// from the centroid with RC_DECOMP_NEAR_TOUCHING (every triangle with a point within alpha of p
// has its centroid within that reach). Cell c lists, ascending, the triangles that may be in the
// near set of a point of it; the kernel tests each (rc_decomp_in_near_set).
RecordGridData build_near_grid(const std::vector<shared::NearTriangle>& triangles, float alpha,
                               int rule);

}  // namespace rc
