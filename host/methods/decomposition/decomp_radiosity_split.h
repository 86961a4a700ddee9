// The split triangles' coarse radiosity on several devices (§6 pass 1 with
// --decomp-radiosity coarse and path-traced continuation as the coarse solution): the listed
// triangles in ranges shared among the devices (methods/device_split.h). A triangle's B(t) reads
// only its own points and random streams (triangle t, point k), so it does not depend on the
// device; the host gathers them by range into the first device's buffer. The triangles are
// uploaded to each peer. With the grid as the coarse solution the rays read the grid on the first
// device, where this stays.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "device/buffer.h"
#include "methods/frame_scene.h"
#include "shared/decomposition.h"
#include "shared/types.h"

namespace rc {

// One device's share of the coarse radiosity: triangles and rays.
struct DecompRadiosityShare {
    size_t triangles = 0;
    uint64_t rays = 0;
    double seconds = 0.0;
};

// B(t) / pi of the triangles `listed` (path-traced continuation) into `radiance` on the first
// device of `frame` (its other entries kept), shared with frame.peers (not empty). The rays
// traced; each device's share in *shares (one entry per device, the first device first).
uint64_t split_coarse_radiosity(const FrameScene& frame, const shared::DecompParams& params,
                                const std::string& build_options,
                                const std::vector<shared::NearTriangle>& triangles,
                                const Buffer<shared::NearTriangle>& first_triangles,
                                const std::vector<uint32_t>& listed,
                                Buffer<shared::float4>& radiance,
                                std::vector<DecompRadiosityShare>* shares);

}  // namespace rc
