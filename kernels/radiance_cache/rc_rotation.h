// Aligning a record's coefficient vectors with the frame of a query point (DESIGN.md §6.4; course
// "Rotation"; TVCG 2005 §4.4 eq. 12's R_i): the 3x3 rotation between two local frames that
// shared/sh_rotation.h's rc_sh_rotate takes.
#pragma once

#include "common/math.h"
#include "shared/sh_rotation.h"

// R with d_to = R d_from for the local coordinates of one world direction in the two frames:
// R[3 a + b] = (axis a of `to`) . (axis b of `from`), axes t, b, n.
RC_FUNC void rc_frame_rotation(const Frame* from, const Frame* to, float* rotation) {
    const float3 to_axes[3] = {to->t, to->b, to->n};
    const float3 from_axes[3] = {from->t, from->b, from->n};
    for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) {
            rotation[3 * a + b] = dot(to_axes[a], from_axes[b]);
        }
    }
}
