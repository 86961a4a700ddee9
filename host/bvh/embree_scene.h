// Embree's own intersector over the same triangles: the oracle of the traversal tests and the
// anchor of `radcache bench rays`.
#pragma once

#include <embree3/rtcore.h>

#include <vector>

#include "bvh/embree_device.h"
#include "scene/triangle_mesh.h"
#include "shared/types.h"

namespace rc {

class EmbreeScene {
   public:
    // A robust (watertight-mode) scene of one triangle geometry; primitive i is
    // mesh.triangles[i].
    explicit EmbreeScene(const TriangleMesh& mesh);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // rtcIntersect1: the closest hit in (tmin, tmax], primitive RC_NO_HIT when none.
    shared::Hit intersect(const shared::Ray& ray) const;
    // rtcOccluded1: whether anything is hit in (tmin, tmax].
    bool occluded(const shared::Ray& ray) const;

    // The same over a batch, split over `threads` threads.
    void intersect(const std::vector<shared::Ray>& rays, std::vector<shared::Hit>& hits,
                   unsigned threads) const;
    void occluded(const std::vector<shared::Ray>& rays, std::vector<unsigned>& occluded,
                  unsigned threads) const;

   private:
    EmbreeDevice device_;
    RTCScene scene_ = nullptr;
};

// Whether two tracers found the same closest hit: the same primitive (both may have missed), or
// two triangles tying at a shared edge or vertex: t equal within 1e-5 relative.
bool same_closest_hit(const shared::Hit& a, const shared::Hit& b);

}  // namespace rc
