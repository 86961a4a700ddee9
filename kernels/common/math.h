// Constants and small vector helpers of the device code.
#pragma once

#include "shared/types.h"

#define RC_PI 3.14159265358979323846f
#define RC_INV_PI 0.31830988618379067154f
#define RC_INV_TWO_PI 0.15915494309189533577f
#define RC_INV_FOUR_PI 0.07957747154594766788f

RC_FUNC float rc_luminance(float3 rgb) { return dot(rgb, (float3)(0.2126f, 0.7152f, 0.0722f)); }

RC_FUNC float rc_max_component(float3 v) { return fmax(v.x, fmax(v.y, v.z)); }

RC_FUNC bool rc_is_black(float3 v) { return v.x <= 0.0f && v.y <= 0.0f && v.z <= 0.0f; }

// Power heuristic with beta = 2 (Veach 1997, §9.2.4): the weight of a sample drawn with pdf `a`
// when the other strategy would have drawn it with pdf `b`.
RC_FUNC float rc_power_heuristic(float a, float b) {
    const float a2 = a * a;
    const float b2 = b * b;
    return (a2 + b2) > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

// A local shading frame: tangent, bitangent, normal.
typedef struct Frame {
    float3 t, b, n;
} Frame;

RC_FUNC float3 rc_to_local(const Frame* f, float3 v) {
    return (float3)(dot(v, f->t), dot(v, f->b), dot(v, f->n));
}

RC_FUNC float3 rc_from_local(const Frame* f, float3 v) {
    return v.x * f->t + v.y * f->b + v.z * f->n;
}
