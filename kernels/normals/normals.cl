// Entry kernel of the geometry preview (host/methods/normals/normals.cpp).
#include "common/kernel_range.h"
#include "normals/normals.h"

RC_KERNEL void render_normals(uint begin, uint end, CameraParams camera,
                              __global const TraversalNode* nodes,
                              __global const Triangle* triangles,
                              __global const uint* triangle_of_primitive, uint first, uint samples,
                              uint jitter, uint seed_lo, uint seed_hi, __global float4* film) {
    RC_RANGE_ITEM(pixel);
    film[pixel] = rc_normals_pixel(&camera, nodes, triangles, triangle_of_primitive, pixel, first,
                                   samples, jitter, seed_lo, seed_hi);
}
