// Compatibility layer between OpenCL C and C++. The files in kernels/shared/ compile as both;
// OpenCL-only syntax (address spaces, built-ins, extensions) is named here and nowhere else in
// kernels/shared/ and kernels/common/.
#pragma once

#ifdef __OPENCL_VERSION__

#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#define RC_HAS_DOUBLE 1
#endif

#ifdef cl_khr_int64_base_atomics
#pragma OPENCL EXTENSION cl_khr_int64_base_atomics : enable
#endif

#define RC_SHARED_BEGIN
#define RC_SHARED_END
#define RC_FUNC static inline
#define RC_GLOBAL __global
#define RC_CONSTANT __constant
#define rc_mul_hi(a, b) mul_hi((a), (b))
#define rc_as_uint(x) as_uint(x)
#define rc_as_float(x) as_float(x)
#define rc_as_int(x) as_int(x)
#define rc_offsetof(type, field) __builtin_offsetof(type, field)
#define rc_shuffle(v, mask) shuffle((v), (mask))
// 64-bit integer atomic addition (cl_khr_int64_base_atomics; the irradiance vector grid's
// fixed-point sums).
#define rc_atomic_add_long(pointer, value) atom_add((pointer), (value))
// At the start of a block: no fused multiply-adds in it (needed where a computation must be
// exactly antisymmetric, like the edge functions of the watertight triangle test).
#define RC_NO_FP_CONTRACT _Pragma("OPENCL FP_CONTRACT OFF")

#else  // C++ host

#include <cstddef>
#include <cstdint>
#include <cstring>

#define RC_SHARED_BEGIN namespace rc::shared {
#define RC_SHARED_END }
#define RC_FUNC inline
#define RC_GLOBAL
#define RC_CONSTANT
#define rc_offsetof(type, field) offsetof(type, field)
#define RC_NO_FP_CONTRACT _Pragma("STDC FP_CONTRACT OFF")

namespace rc::shared {

using uint = unsigned int;
using uchar = unsigned char;

// OpenCL's 4-wide vectors are 16-byte aligned; these host twins have the same size and alignment.
struct alignas(16) float4 {
    float x, y, z, w;
};
struct alignas(16) int4 {
    int x, y, z, w;
};
struct alignas(16) uint4 {
    uint x, y, z, w;
};

inline uint rc_mul_hi(uint a, uint b) {
    return static_cast<uint>((static_cast<uint64_t>(a) * b) >> 32);
}
inline uint rc_as_uint(float x) {
    uint u;
    std::memcpy(&u, &x, sizeof u);
    return u;
}
inline float rc_as_float(uint u) {
    float x;
    std::memcpy(&x, &u, sizeof x);
    return x;
}

}  // namespace rc::shared

#endif
