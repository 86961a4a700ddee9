// Irradiance decomposition's pass 2 on several devices (IrradianceDecomposition with the
// frame's peers): both terms at the camera samples (decomp_irradiance) and the render pass
// (decomp_shade) in chunks of rows, shared among the devices (methods/device_split.h). A camera
// sample's terms read only its own G-buffer entry and the near and far fields, and a pixel's
// shading only its own samples' terms, so neither depends on the device that computed it; the
// host merges the terms and the film by chunk. What every device reads (the camera samples, the
// split triangles and their radiosity, the far-field samples and both grids) is made once on the
// first device and host, and uploaded to each peer. The image is bitwise the one-device image on
// identical devices, whatever the split.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "device/buffer.h"
#include "methods/caching/record_grid.h"
#include "methods/frame_scene.h"
#include "shared/decomposition.h"
#include "shared/types.h"

namespace rc {

// One device's share of a decomposed frame's pass 2.
struct DecompDeviceShare {
    std::string device;  // "P:D name"
    // The cluster batches (--decomp-source path; decomp_cluster_split.h): cluster ranges, their
    // clusters and rays, and its threads' time over the batches.
    // The coarse radiosity (--decomp-source path, --decomp-radiosity coarse;
    // decomp_radiosity_split.h): split triangles, their rays, its thread's time.
    size_t radiosity_triangles = 0;
    uint64_t radiosity_rays = 0;
    double radiosity_seconds = 0.0;
    size_t cluster_ranges = 0;
    size_t clusters = 0;
    uint64_t cluster_rays = 0;
    double cluster_seconds = 0.0;
    size_t chunks = 0;          // chunks of rows it evaluated and shaded
    size_t pixels = 0;          // their pixels
    uint64_t shading_rays = 0;  // its render pass's rays
    double seconds = 0.0;       // its thread's time in pass 2
};

// The near and far fields as the first device holds them (pass 1's result).
struct DecompFields {
    const RecordGridData& far_grid;
    const Buffer<int>& far_start;
    const Buffer<int>& far_list;
    const Buffer<shared::Record>& far_records;
    const Buffer<shared::ShSample>& far_coefficients;
    const Buffer<shared::ShGradient>& far_gradients;  // all zero without --decomp-gradients on
    const RecordGridData& near_grid;
    const Buffer<int>& near_start;
    const Buffer<int>& near_list;
    const Buffer<shared::NearTriangle>& triangles;
    const Buffer<shared::float4>& radiance;  // B(t) / pi of the split triangles
};

struct DecompPassInput {
    const shared::DecompParams& params;
    const shared::CameraParams& camera;
    const std::string& build_options;              // the program's, for the coarse solution's kind
    const Buffer<shared::GBufferSample>& gbuffer;  // the camera samples, on the first device
    const std::vector<shared::GBufferSample>& samples;  // the same, on the host
    DecompFields fields;
};

// Pass 2's result, merged by chunk: the terms at every camera sample (entry pixel * spp + s), the
// film's sums (RC_DECOMP_FILM_SLOTS per pixel) and the render pass's counters.
struct DecompPassOutput {
    std::vector<shared::DecompIrradiance> terms;
    std::vector<shared::float4> film;
    uint64_t shading_rays = 0;
    uint64_t nonfinite_samples = 0;
    int64_t first_nonfinite_pixel = -1;
    double evaluation_seconds = 0.0;  // both passes, chunk by chunk
    std::vector<DecompDeviceShare> shares;
};

// Pass 2 of `input` on `frame`'s device and its peers (frame.peers: not empty).
DecompPassOutput decomp_device_pass(const FrameScene& frame, const DecompPassInput& input);

}  // namespace rc
