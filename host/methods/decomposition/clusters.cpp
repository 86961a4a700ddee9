#include "methods/decomposition/clusters.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace rc {
namespace {

// A point of the k-means: position and normal times the cluster's radius, as 6 numbers.
struct Feature {
    glm::vec3 position;
    glm::vec3 normal;
};

float distance2(const Feature& a, const Feature& b) {
    const glm::vec3 p = a.position - b.position;
    const glm::vec3 n = a.normal - b.normal;
    return glm::dot(p, p) + glm::dot(n, n);
}

// The index (into `features`) of the one farthest from `from` (the first on ties).
size_t farthest(const std::vector<Feature>& features, const Feature& from) {
    size_t best = 0;
    float best_distance = -1.0f;
    for (size_t i = 0; i < features.size(); ++i) {
        const float d = distance2(features[i], from);
        if (d > best_distance) {
            best_distance = d;
            best = i;
        }
    }
    return best;
}

// The mean of features[i] over i with side[i] == which (all of them when which < 0), summed in
// double in order; false when there is none.
bool mean_of(const std::vector<Feature>& features, const std::vector<uint8_t>& side, int which,
             Feature* out) {
    glm::dvec3 p(0.0);
    glm::dvec3 n(0.0);
    size_t count = 0;
    for (size_t i = 0; i < features.size(); ++i) {
        if (which < 0 || side[i] == which) {
            p += glm::dvec3(features[i].position);
            n += glm::dvec3(features[i].normal);
            ++count;
        }
    }
    if (count == 0) {
        return false;
    }
    out->position = glm::vec3(p / static_cast<double>(count));
    out->normal = glm::vec3(n / static_cast<double>(count));
    return true;
}

}  // namespace

PointCluster make_cluster(const ShadingPoints& points, std::vector<uint32_t> members) {
    PointCluster c;
    c.members = std::move(members);
    if (c.members.empty()) {
        return c;
    }
    glm::dvec3 position(0.0);
    glm::dvec3 normal(0.0);
    for (uint32_t m : c.members) {
        position += glm::dvec3(points.positions[m]);
        normal += glm::dvec3(points.normals[m]);
    }
    c.centre = glm::vec3(position / static_cast<double>(c.members.size()));
    c.normal = glm::vec3(normal / static_cast<double>(c.members.size()));
    float radius2 = 0.0f;
    for (uint32_t m : c.members) {
        const glm::vec3 d = points.positions[m] - c.centre;
        radius2 = std::max(radius2, glm::dot(d, d));
    }
    c.radius = std::sqrt(radius2);
    return c;
}

std::pair<std::vector<uint32_t>, std::vector<uint32_t>> split_in_two(const ShadingPoints& points,
                                                                     const PointCluster& cluster,
                                                                     int iterations) {
    std::pair<std::vector<uint32_t>, std::vector<uint32_t>> halves;
    const std::vector<uint32_t>& members = cluster.members;
    if (members.empty()) {
        return halves;
    }
    std::vector<Feature> features(members.size());
    for (size_t i = 0; i < members.size(); ++i) {
        features[i] = {points.positions[members[i]], cluster.radius * points.normals[members[i]]};
    }
    std::vector<uint8_t> side(members.size(), 2);
    Feature mean;
    mean_of(features, side, -1, &mean);
    const size_t first = farthest(features, mean);
    const size_t second = farthest(features, features[first]);
    Feature seed[2] = {features[first], features[second]};
    if (!(distance2(seed[0], seed[1]) > 0.0f)) {
        halves.first = members;
        return halves;
    }
    for (int iteration = 0; iteration < iterations; ++iteration) {
        bool changed = false;
        for (size_t i = 0; i < features.size(); ++i) {
            const uint8_t s = distance2(features[i], seed[1]) < distance2(features[i], seed[0]);
            changed = changed || s != side[i];
            side[i] = s;
        }
        if (!changed) {
            break;
        }
        for (int k = 0; k < 2; ++k) {
            mean_of(features, side, k, &seed[k]);
        }
    }
    for (size_t i = 0; i < members.size(); ++i) {
        (side[i] == 0 ? halves.first : halves.second).push_back(members[i]);
    }
    if (halves.first.empty()) {
        std::swap(halves.first, halves.second);
    }
    return halves;
}

bool needs_split(const PointCluster& cluster, uint32_t inside_hits, float min_diameter,
                 uint32_t min_points) {
    return inside_hits > 0 && 2.0f * cluster.radius >= min_diameter &&
           cluster.members.size() >= 2 * static_cast<size_t>(min_points);
}

}  // namespace rc
