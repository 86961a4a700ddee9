// Rendering with the irradiance vector grid (DESIGN.md §6.3; `radcache render --method ivg` and
// `--method ivg-gather`): direct light by next-event estimation at the camera's hit and the
// diffuse lobe's indirect light from the grid, read at the hit itself (ivg: no gather rays) or
// at the hits of cosine-distributed gather rays (ivg-gather: final gathering); other lobes by
// path tracing. Schedules the render pass; the grid belongs to IrradianceVectorGrid.
#pragma once

#include <cstdint>

#include "image/image.h"
#include "methods/frame_scene.h"
#include "methods/grid/irradiance_vector_grid.h"
#include "methods/shared_settings.h"

namespace rc {

struct IvgRenderOptions : SharedSettings {
    IvgRenderOptions() { spp = 4; }
    int gather_rays = 0;    // per camera sample; 0: read the grid at the camera's hit (ivg)
    int light_samples = 1;  // light samples of the direct light at the camera's hit
    // The first camera sample index: the render draws samples first_sample .. first_sample +
    // spp - 1 of every pixel (a pass of a render by time; its image their mean).
    int first_sample = 0;
};

struct IvgRenderStats {
    uint64_t rays = 0;
    double seconds = 0.0;
    uint64_t nonfinite_samples = 0;
    int64_t first_nonfinite_pixel = -1;
};

// The layers of an image rendered with the grid, in channel order (3 channels each): beauty
// (R, G, B), direct, indirect, albedo, normal, grid (the grid's diffuse light at the camera's
// hit, rho_d / pi E: the grid-only indirect light).
extern const char* const kIvgAovs[6];

class IvgMethod : private FrameBound {
   public:
    IvgMethod(const FrameScene& frame, const IrradianceVectorGrid& grid);

    Image render(const IvgRenderOptions& options, IvgRenderStats* stats = nullptr);

   private:
    const IrradianceVectorGrid& grid_;
    Kernel shade_kernel_;
};

}  // namespace rc
