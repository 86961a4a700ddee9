// Radiance caching's BRDF tables for a scene's materials (DESIGN.md §6.4; TVCG 2005 §4.1): built
// on the device at scene load (kernels/radiance_cache/radiance_cache.cl, rc_brdf_table_texels),
// each material's order chosen adaptively, and kept in device buffers that the radiance-caching
// kernels read with kernels/radiance_cache/rc_brdf_table.h.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "device/buffer.h"
#include "scene/material.h"
#include "shared/radiance_cache.h"

namespace rc {

class Context;

struct BrdfTableOptions {
    int resolution = 32;  // texels per side of the parabolic map (HSH paper §5: 32 x 32)
    int max_order = RC_SH_MAX_ORDER;  // n_max: lobes needing more go to Monte Carlo
    double max_error = 0.1;           // the largest representation error a table may have
    int basis = RC_BASIS_SH;          // RC_BASIS_SH (what records use) or RC_BASIS_HSH
    int theta_nodes = 64;             // Gauss-Legendre nodes in cos(theta_i)
    int phi_nodes = 128;              // midpoint nodes in phi_i
};

// Error (exit status 2) naming the first option out of range: resolution in [2, 256],
// max_order in [1, RC_SH_MAX_ORDER], max_error in (0, 1), basis RC_BASIS_SH or RC_BASIS_HSH,
// theta_nodes in [RC_SH_MAX_ORDER, 1024], phi_nodes in [2 RC_SH_MAX_ORDER, 4096].
void check_brdf_table_options(const BrdfTableOptions& options);

// What the adaptive order made of one material.
struct BrdfTableSummary {
    std::string name;
    int kind = RC_BRDF_DIFFUSE;      // RC_BRDF_*
    int order = 0;                   // highest order a represented direction needs (0: none)
    double fallback_fraction = 0.0;  // solid-angle fraction of directions left to Monte Carlo
    // Over the outgoing directions of the hemisphere (texel centres inside the disk): the
    // smallest and the largest representation error at n_max.
    double min_error_at_max_order = 0.0;
    double max_error_at_max_order = 0.0;
};

const char* brdf_kind_name(int kind);

class BrdfTables {
   public:
    // Builds the tables of every material with a specular lobe (one launch per material) and
    // chooses the orders: a texel's order is the lowest n <= max_order whose error is at most
    // max_error, else 0 (Monte Carlo); a material's is the highest over the texels whose centre
    // is an outgoing direction (inside the disk).
    BrdfTables(Context& context, const std::vector<Material>& materials,
               const BrdfTableOptions& options = {});

    const BrdfTableOptions& options() const { return options_; }
    // One entry per material, in the scene's order.
    const std::vector<shared::BrdfTableInfo>& infos() const { return infos_; }
    const std::vector<BrdfTableSummary>& summaries() const { return summaries_; }
    // Every table's texel errors, texel t's error at order n at [t * RC_SH_MAX_ORDER + n - 1].
    const std::vector<float>& texel_errors() const { return texel_errors_; }
    const std::vector<int>& texel_orders() const { return texel_orders_; }

    // Device buffers: infos (per material), coefficients (RC_SH_MAX_COEFFICIENTS per texel),
    // orders (per texel).
    const Buffer<shared::BrdfTableInfo>& device_infos() const { return device_infos_; }
    const Buffer<float>& coefficients() const { return coefficients_; }
    const Buffer<int>& orders() const { return orders_; }
    size_t texel_count() const { return texel_orders_.size(); }
    size_t bytes() const;

   private:
    void choose_orders(const std::vector<Material>& materials);

    BrdfTableOptions options_;
    std::vector<shared::BrdfTableInfo> infos_;
    std::vector<BrdfTableSummary> summaries_;
    std::vector<float> texel_errors_;
    std::vector<int> texel_orders_;
    Buffer<shared::BrdfTableInfo> device_infos_;
    Buffer<float> coefficients_;
    Buffer<int> orders_;
};

// The tables of `materials` for `options`, built once per context: a later render on the same
// device with the same materials (the next frame under `ic --glossy`, --method auto's render after
// its pilot) gets the same tables without building them again (Context::derived). *built: whether
// this call built them.
std::shared_ptr<const BrdfTables> shared_brdf_tables(Context& context,
                                                     const std::vector<Material>& materials,
                                                     const BrdfTableOptions& options,
                                                     bool* built = nullptr);

}  // namespace rc
