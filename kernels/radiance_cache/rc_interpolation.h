// One radiance record's contribution to a query point on a glossy surface (DESIGN.md §6.4;
// TVCG 2005 §4.4 eq. 12, the course's "Interpolation" and "Outgoing Radiance Computation"
// slides): the record's coefficient vectors, adjusted by its translational gradients for the
// displacement (dx, dy) of the query in the record's frame ("Improved Radiance Gradient
// Computation" §3: the gradients apply before the rotation, in the record's frame), rotated into
// the query's frame and dotted with the BRDF's coefficient vector there:
//   L_o = < D(R) (lambda + dx dlambda/dx + dy dlambda/dy), b(w_o) >.
// D(R) is orthogonal, so < D(R) c, b > = < c, D(R^T) b >: the BRDF's one vector is rotated into the
// record's frame instead of the three channels into the query's (a third of the work), by the
// zxzxz factorization (shared/sh_rotation_zxz.h).
#pragma once

#include "shared/sh_rotation_zxz.h"

// `coefficients`: r, g, b vectors (3 order^2); `gradients`: r x, r y, g x, g y, b x, b y
// (6 order^2, rc_project_cells_with_gradients's layout); `rotation`: record frame -> query frame
// (rc_frame_rotation); `brdf`: order^2 coefficients in the query's frame, overwritten by their
// rotation into the record's frame. Returns the reflected radiance per channel.
RC_FUNC float3 rc_record_reflection(const float* coefficients, const float* gradients, int order,
                                    float dx, float dy, const float* rotation,
                                    RC_GLOBAL const float* x90, float* brdf) {
    const float inverse[9] = {rotation[0], rotation[3], rotation[6], rotation[1], rotation[4],
                              rotation[7], rotation[2], rotation[5], rotation[8]};
    const int count = rc_sh_count(order);
    rc_sh_rotate_zxz(inverse, x90, order, brdf, 1, count);
    float sums[3];
    for (int c = 0; c < 3; ++c) {
        const float* lambda = coefficients + c * count;
        const float* gx = gradients + 2 * c * count;
        const float* gy = gx + count;
        float sum = 0.0f;
        for (int i = 0; i < count; ++i) {
            sum += (lambda[i] + dx * gx[i] + dy * gy[i]) * brdf[i];
        }
        sums[c] = sum;
    }
    return (float3)(sums[0], sums[1], sums[2]);
}
