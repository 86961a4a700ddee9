// Entry kernels that make batches of rays (tests and `radcache bench rays`).
#include "common/camera.h"
#include "common/diffuse_bounce.h"
#include "common/kernel_range.h"

// One centred camera ray per pixel, row by row from the top-left pixel.
RC_KERNEL void spawn_camera_rays(uint begin, uint end, CameraParams camera, __global Ray* rays) {
    RC_RANGE_ITEM(i);
    const uint x = i % (uint)camera.resolution.x;
    const uint y = i / (uint)camera.resolution.x;
    rays[i] = rc_camera_ray(&camera, (float)x + 0.5f, (float)y + 0.5f);
}

// A cosine-distributed bounce ray from the hit of every ray (zero direction where it missed).
RC_KERNEL void spawn_diffuse_rays(uint begin, uint end, __global const Ray* rays,
                                  __global const Hit* hits, __global const Triangle* triangles,
                                  __global const uint* triangle_of_primitive, uint seed_lo,
                                  uint seed_hi, __global Ray* bounces) {
    RC_RANGE_ITEM(i);
    RngStream rng = rc_rng_stream(seed_lo, seed_hi, i, 0u);
    bounces[i] = rc_diffuse_bounce_ray(rays[i], hits[i], triangles, triangle_of_primitive, &rng);
}
