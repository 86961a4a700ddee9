// The reference path tracer (DESIGN.md §6.1; kernels/path_tracer.h): progressive, one sample per
// pixel per pass, to a sample count or a time budget. Owns the film; reports its statistics.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "image/image.h"
#include "methods/frame_scene.h"
#include "methods/shared_settings.h"
#include "shared/types.h"

namespace rc {

struct PathTracerOptions : SharedSettings {
    double time_limit = 0.0;  // > 0: render passes until this many seconds have passed
    // Called after passes 1, 2, 4, 8, ... with the image so far.
    std::function<void(int spp, const Image& image)> on_power_of_two;
    // Called after each pass with the fraction done (of spp or of the time limit).
    std::function<void(double fraction, int spp)> on_progress;
    // When set, receives the film's sums (image/sample_sums.h) of the rendered pixels.
    Image* sums = nullptr;
};

// One device's share of a render on several devices (PathTracer::render with peers).
struct PathTracerDeviceShare {
    std::string device;  // "P:D name"
    size_t chunks = 0;   // pixel chunks it rendered
    size_t pixels = 0;
    uint64_t rays = 0;
    double seconds = 0.0;  // its thread's time from start to its last chunk
};

struct PathTracerStats {
    std::vector<PathTracerDeviceShare> devices;  // with peers: per device, the render's first
    int spp = 0;
    double seconds = 0.0;
    uint64_t rays = 0;
    uint64_t nonfinite_samples = 0;  // dropped; each names a bug
    int64_t first_nonfinite_pixel = -1;
};

// The AOV layers of a path-traced image, in channel order (3 channels each): beauty (R, G, B),
// then direct, indirect, albedo, normal and stddev (the standard deviation of one beauty sample
// of the pixel, the unbiased sample estimate; the mean's is stddev / sqrt(spp)).
extern const char* const kPathTracerAovs[6];

// Error (exit status 2) naming the resolution when its film cannot be one buffer on `device`.
void check_film_size(int width, int height, const DeviceInfo& device);

class PathTracer : private FrameBound {
   public:
    explicit PathTracer(const FrameScene& frame);

    // With the frame's peers (several devices), the pixels are split into chunks of rows that
    // the devices take in turn as they finish the last (faster devices take more); a device
    // renders every pass of a chunk, so a pixel's sum of samples is the one device's in pass
    // order: the image is bitwise the one-device image on identical devices, whatever the split.
    // --time and intermediate images (on_power_of_two) need one device (Error, exit status 2).
    // With options.crop, only the window's pixels are traced, each with the samples (seeded by
    // its index in the whole image) it has in the whole render, and the image is the window's;
    // with options.first_sample, the passes draw samples first_sample .. first_sample + spp - 1.
    // Both render on one device (Error, exit status 2, with peers).
    Image render(const PathTracerOptions& options, PathTracerStats* stats = nullptr);

   private:
    // The kernel's parameters but the pass (params.sample).
    static shared::PathTracerParams pass_params(const PathTracerOptions& options, int width,
                                                int height);
    // The film's sums (of the whole image, `width` pixels a row) in `window` as the image of
    // means and standard deviations; *sums_out, when given, receives the sums.
    static Image resolve(const std::vector<shared::float4>& film, int width,
                         const PixelWindow& window, Image* sums_out = nullptr);
    // Passes first .. first + spp - 1 over the pixels of `window` (or until the time limit).
    PathTracerStats render_passes(const PathTracerOptions& options, const PixelWindow& window,
                                  Buffer<shared::float4>& film);
    Image render_split(const PathTracerOptions& options, int width, int height,
                       PathTracerStats* stats);

    FrameScene frame_;
    Kernel kernel_;
};

}  // namespace rc
