// Radiance cache splatting (course, "Radiance Cache Splatting", §4.1 Algorithm 1 and §4.2
// Algorithm 2) as the camera samples read it: the host splats every record's influence sphere
// (radius a R, eq. 4) onto the image as the bounding rectangle of its projection, into the screen
// tiles it covers, in record order (host/methods/caching/splat_tiles.h); a camera sample
// accumulates the weighted contribution w E' (eqs. 2 and 8, with the "Weighting Function
// Revisited" shift) of its tile's records in that order into the splat buffer (sum w E', sum w):
// the sums a GPU's ordered blending of the records' quads gives, without atomics.
#pragma once

#include "caching/irradiance_records.h"

// Candidate q of a placement pass (params->placement_*), as a G-buffer index: with C candidate
// columns, stride s and S samples per candidate pixel, camera sample q % S of pixel
// (s (q / S % C), s (q / S / C)); with stride 0, entry q itself.
RC_FUNC uint rc_ic_candidate(const IcParams* params, uint q) {
    const uint stride = (uint)params->placement_stride;
    const uint per_pixel = (uint)max(params->placement_spp, 1);
    const uint columns = (uint)max(params->placement_columns, 1);
    const uint c = q / per_pixel;
    const uint x = stride * (c % columns);
    const uint y = stride * (c / columns);
    return stride == 0 ? q
                       : (y * (uint)params->width + x) * (uint)params->camera_spp + q % per_pixel;
}

// The screen tile of camera sample i (G-buffer entry i of an image of params->width pixels a
// row, params->camera_spp samples a pixel).
RC_FUNC uint rc_ic_sample_tile(const IcParams* params, const SplatTileGrid* tiles, uint i) {
    const uint pixel = i / (uint)params->camera_spp;
    const uint x = pixel % (uint)params->width;
    const uint y = pixel / (uint)params->width;
    return (y / (uint)tiles->tile_size) * (uint)tiles->tiles_x + x / (uint)tiles->tile_size;
}

// The (nearest, farthest) distance from the eye of the served camera samples of tile t.
RC_FUNC TileDepths rc_ic_tile_depths(const IcParams* params, const CameraParams* camera,
                                     const SplatTileGrid* tiles,
                                     RC_GLOBAL const GBufferSample* gbuffer, uint t) {
    const uint x0 = (t % (uint)tiles->tiles_x) * (uint)tiles->tile_size;
    const uint y0 = (t / (uint)tiles->tiles_x) * (uint)tiles->tile_size;
    const uint x1 = min(x0 + (uint)tiles->tile_size, (uint)params->width);
    const uint y1 = min(y0 + (uint)tiles->tile_size, (uint)params->height);
    TileDepths depths = {INFINITY, -INFINITY};
    for (uint y = y0; y < y1; ++y) {
        for (uint x = x0; x < x1; ++x) {
            for (uint s = 0; s < (uint)params->camera_spp; ++s) {
                RC_GLOBAL const GBufferSample* g =
                    gbuffer + ((size_t)y * (uint)params->width + x) * (uint)params->camera_spp + s;
                if (g->served != 0) {
                    const float d = length(g->position.xyz - camera->origin.xyz);
                    depths.nearest = fmin(depths.nearest, d);
                    depths.farthest = fmax(depths.farthest, d);
                }
            }
        }
    }
    return depths;
}

// The splat buffer's entry of camera sample i at (p, n): the weighted sum over the records
// splatted into its pixel's tile.
RC_FUNC float4 rc_ic_splat_sum(const IcParams* params, const SplatTileGrid* tiles,
                               RC_GLOBAL const int* tile_start, RC_GLOBAL const int* tile_records,
                               RC_GLOBAL const Record* records,
                               RC_GLOBAL const IrradiancePayload* payloads, uint i, float3 p,
                               float3 n) {
    const uint tile = rc_ic_sample_tile(params, tiles, i);
    return rc_ic_weighted_sum(tile_records, tile_start[tile], tile_start[tile + 1], records,
                              payloads, p, n, params->accuracy, params->max_weight);
}
