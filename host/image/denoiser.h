// Intel Open Image Denoise (OIDN) in process: its `RT` filter on a render's beauty, with the
// render's albedo and normal layers as auxiliary images. Debian has no OIDN package, so the
// library is loaded at run time (dlopen) from the first of: the path given (render's
// --denoise-library), $RADCACHE_OIDN_LIBRARY, libOpenImageDenoise.so.2 on the loader's search
// path, and the copy the pip package pyoidn ships (found through python3).
#pragma once

#include <memory>
#include <string>

#include "image/image.h"

namespace rc {

// The filter's quality (OIDN's OIDN_QUALITY_*): "high" (final frames), "balanced", "fast".
int denoise_quality(const std::string& name);

class Denoiser {
   public:
    // Loads the library and makes its CPU device; Error in one line naming every place looked at
    // and why each failed (exit status 2: the render cannot be what was asked), or OIDN's own
    // message when its device fails (exit status 1).
    static std::unique_ptr<Denoiser> load(const std::string& library, int quality);
    ~Denoiser();
    Denoiser(const Denoiser&) = delete;
    Denoiser& operator=(const Denoiser&) = delete;

    // The image with its beauty (R, G, B) denoised and the noisy beauty kept as the layer
    // beauty_noisy (after the beauty's channels); every other layer as it was. The image must
    // have albedo and normal layers (Error naming the missing one otherwise); the auxiliaries are
    // taken as noisy (averaged over a pixel's samples like the beauty), the beauty as HDR.
    // Non-finite input pixels are refused by OIDN, so they are read as 0.
    Image denoise(const Image& image) const;

    // Seconds a width x height denoise is predicted to take: a set-up time plus a cost per pixel,
    // fitted on first use to denoises of 64² and 128² after one of 32² (OIDN's first run, which
    // loads its weights, excluded).
    double predicted_seconds(int width, int height);

    const std::string& library_path() const { return path_; }

   private:
    struct Api;
    Denoiser() = default;
    void calibrate();
    void run(const float* colour, const float* albedo, const float* normal, float* output,
             int width, int height) const;

    std::unique_ptr<Api> api_;
    std::string path_;
    int quality_ = 0;
    double seconds_per_pixel_ = 0.0;
    double setup_seconds_ = 0.0;
};

}  // namespace rc
