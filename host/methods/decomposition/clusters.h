// Clusters of shading points (Arikan, Forsyth and O'Brien 2005, §4.1; course, "Implementation
// Details 2/3": "hierarchical vector quantization to cluster these surface locations"): a set of
// points, its centre, mean normal and bounding sphere, its split into two by k-means, and the
// paper's rule for when a cluster's far-field sample is good enough.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <utility>
#include <vector>

namespace rc {

// The shading points the clusters partition: position and unit normal of each.
struct ShadingPoints {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
};

struct PointCluster {
    std::vector<uint32_t> members;  // indices into the points, ascending
    glm::vec3 centre{0.0f};         // the members' mean position ("the geometric center", §4.1)
    glm::vec3 normal{0.0f};         // the members' mean normal (not normalised)
    float radius = 0.0f;            // of the bounding sphere about the centre
};

// The cluster of `members` (ascending indices into `points`).
PointCluster make_cluster(const ShadingPoints& points, std::vector<uint32_t> members);

// The cluster's members in two by 2-means (§4.1: "we split (using k-means) the set of shading
// points into two") on their positions and their normals scaled by the cluster's radius, so
// that a cluster spanning a crease parts along it: the far-field fit of one orientation's points
// gives their irradiance without the bias a mix of hemispheres brings (docs/decomposition.md).
// Seeded by the member farthest from the mean and the member farthest from that one (the first in
// member order on ties), then Lloyd iterations until no member changes side (at most
// `iterations`). Deterministic. Both halves are ascending; the second is empty when the members
// cannot be separated (all alike).
std::pair<std::vector<uint32_t>, std::vector<uint32_t>> split_in_two(const ShadingPoints& points,
                                                                     const PointCluster& cluster,
                                                                     int iterations = 16);

// §4.1: a cluster's sample is split "if any of these rays intersects a surface within the
// bounding sphere of the samples ... A set is not split if the diameter of the bounding sphere
// for the shading points in the set is less than alpha, or if the rays do not intersect other
// surfaces within the bounding sphere"; here the diameter's floor is `min_diameter` (the paper's:
// alpha), the rays' test sphere may be larger than the bounding sphere
// (DecompCluster.test_radius), and a cluster of fewer than 2 min_points points is not split (a
// floor on the far field's sampling density in pixels).
bool needs_split(const PointCluster& cluster, uint32_t inside_hits, float min_diameter,
                 uint32_t min_points);

}  // namespace rc
