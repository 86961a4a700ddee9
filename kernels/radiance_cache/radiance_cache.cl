// Entry kernels of radiance caching (DESIGN.md §6.4). Item index: begin + get_global_id(0).
#include "common/kernel_range.h"
#include "radiance_cache/rc_brdf_table.h"

// One texel of one material's BRDF table (rc_brdf_table_texel): its coefficients into
// coefficients[(first_texel + texel) * RC_SH_MAX_COEFFICIENTS ...] and its error at every order
// into errors[(first_texel + texel) * RC_SH_MAX_ORDER ...].
RC_KERNEL void rc_brdf_table_texels(uint begin, uint end, Material material, BrdfTableParams params,
                                    __global const float* nodes, __global float* coefficients,
                                    __global float* errors) {
    RC_RANGE_ITEM(texel);
    float c[RC_SH_MAX_COEFFICIENTS];
    float e[RC_SH_MAX_ORDER];
    rc_brdf_table_texel(&material, &params, (int)texel, nodes, c, e);
    const int at = params.first_texel + (int)texel;
    for (int i = 0; i < RC_SH_MAX_COEFFICIENTS; ++i) {
        coefficients[at * RC_SH_MAX_COEFFICIENTS + i] = c[i];
    }
    for (int n = 0; n < RC_SH_MAX_ORDER; ++n) {
        errors[at * RC_SH_MAX_ORDER + n] = e[n];
    }
}
