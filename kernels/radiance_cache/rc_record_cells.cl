// Entry kernel of radiance caching's hemisphere sampling (host/methods/radiance_cache/): the
// radiance arriving through each cell of a batch of records, the light beyond the hemisphere
// rays' hits read from the source the program is built for (records/radiance_source.h).
#include "common/kernel_range.h"
#include "radiance_cache/rc_records.h"
#include "scene_arguments.h"
// The source after the method's own headers (see records/radiance_source.h).
#include "caching/radiance_source.h"

// Item i: cell i % (M N) of batch record i / (M N) (random stream streams[i / (M N)]), the
// record at sites[i / (M N)]: (L.rgb, distance to the hit) in cells[i], a NaN or infinite
// radiance stored as black. The hemisphere ray is the camera hit's first bounce: the emission it
// sees is direct light, left to the render pass's next-event estimation unless the tests ask for
// it. A direction of the shading normal's hemisphere below the surface's own tangent plane
// (where interpolated normals bend away from the facets) would hit the surface itself: no ray,
// no light, and no neighbour (infinitely far), so a record's radius is not cut to the offset
// of its rays' origin. counters[0] counts the rays traced.
RC_KERNEL void rc_record_cells(uint begin, uint end, RcParams params, RC_SCENE_PARAMETERS,
                               __global const RcQuery* sites, __global const uint* streams,
                               RC_RADIANCE_SOURCE_PARAMETERS __global float4* cells,
                               __global uint* counters) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const RadianceSource source = RC_RADIANCE_SOURCE_DATA();
    const uint per_record = (uint)(params.strata_m * params.strata_n);
    const uint b = i / per_record;
    const uint record = streams[b];
    const int cell = (int)(i % per_record);
    const RcQuery site = sites[b];
    const float3 direction = rc_record_cell_direction(&params, record, cell, site.normal.xyz);
    if (dot(direction, site.geometric_normal.xyz) <= 0.0f) {
        cells[i] = (float4)(0.0f, 0.0f, 0.0f, INFINITY);
        return;
    }
    RngStream rng = rc_record_cell_stream(&params, record, cell);
    Ray ray;
    ray.origin = (float4)(site.origin.xyz, 0.0f);
    ray.direction = (float4)(direction, INFINITY);
    const SourceSample s =
        rc_source_radiance(&scene, &source, ray, &rng, params.count_emission != 0, 1,
                           params.max_depth, params.rr_depth);
    atomic_add(&counters[0], s.rays);
    cells[i] = (float4)(all(isfinite(s.radiance)) ? s.radiance : (float3)(0.0f), s.distance);
}
