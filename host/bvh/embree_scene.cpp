#include "bvh/embree_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

#include "util/error.h"

namespace rc {
namespace {

RTCRay to_embree(const shared::Ray& ray) {
    RTCRay r{};
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.tnear = ray.origin.w;
    r.dir_x = ray.direction.x;
    r.dir_y = ray.direction.y;
    r.dir_z = ray.direction.z;
    r.tfar = ray.direction.w;
    r.time = 0.0f;
    r.mask = std::numeric_limits<unsigned>::max();
    r.id = 0;
    r.flags = 0;
    return r;
}

template <class Work>
void parallel_for(size_t count, unsigned threads, const Work& work) {
    threads = std::max(1u, threads);
    std::vector<std::thread> pool;
    const size_t per_thread = (count + threads - 1) / threads;
    for (unsigned t = 0; t < threads; ++t) {
        const size_t begin = std::min(count, t * per_thread);
        const size_t end = std::min(count, begin + per_thread);
        pool.emplace_back([&work, begin, end] { work(begin, end); });
    }
    for (std::thread& thread : pool) {
        thread.join();
    }
}

}  // namespace

EmbreeScene::EmbreeScene(const TriangleMesh& mesh) {
    scene_ = rtcNewScene(device_.handle());
    device_.check("rtcNewScene");
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geometry = rtcNewGeometry(device_.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), std::max<size_t>(mesh.positions.size(), 1)));
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), mesh.triangles.size()));
    device_.check("rtcSetNewGeometryBuffer");
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        vertices[3 * i + 0] = mesh.positions[i].x;
        vertices[3 * i + 1] = mesh.positions[i].y;
        vertices[3 * i + 2] = mesh.positions[i].z;
    }
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        indices[3 * i + 0] = mesh.triangles[i].x;
        indices[3 * i + 1] = mesh.triangles[i].y;
        indices[3 * i + 2] = mesh.triangles[i].z;
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
    device_.check("rtcCommitScene");
}

EmbreeScene::~EmbreeScene() {
    if (scene_ != nullptr) {
        rtcReleaseScene(scene_);
    }
}

shared::Hit EmbreeScene::intersect(const shared::Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query{};
    query.ray = to_embree(ray);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &query);
    shared::Hit hit{};
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
        hit.t = ray.direction.w;
        hit.primitive = RC_NO_HIT;
        return hit;
    }
    hit.t = query.ray.tfar;
    hit.primitive = query.hit.primID;
    hit.u = query.hit.u;
    hit.v = query.hit.v;
    return hit;
}

bool EmbreeScene::occluded(const shared::Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay query = to_embree(ray);
    rtcOccluded1(scene_, &context, &query);
    // rtcOccluded1 sets tfar to -inf when the ray is occluded.
    return query.tfar == -std::numeric_limits<float>::infinity();
}

void EmbreeScene::intersect(const std::vector<shared::Ray>& rays, std::vector<shared::Hit>& hits,
                            unsigned threads) const {
    hits.resize(rays.size());
    parallel_for(rays.size(), threads, [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            hits[i] = intersect(rays[i]);
        }
    });
}

void EmbreeScene::occluded(const std::vector<shared::Ray>& rays, std::vector<unsigned>& result,
                           unsigned threads) const {
    result.resize(rays.size());
    parallel_for(rays.size(), threads, [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            result[i] = occluded(rays[i]) ? 1u : 0u;
        }
    });
}

bool same_closest_hit(const shared::Hit& a, const shared::Hit& b) {
    if (a.primitive == b.primitive) {
        return true;
    }
    if (a.primitive == RC_NO_HIT || b.primitive == RC_NO_HIT) {
        return false;
    }
    return std::fabs(a.t - b.t) <= 1e-5f * std::max(std::fabs(a.t), std::fabs(b.t));
}

}  // namespace rc
