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
// An entry kernel. Where the host asks for it (RC_SCALAR_WORK_ITEMS, host/device/
// compiler_workarounds.h), compiled for one work item at a time: Intel's CPU compiler, which
// otherwise vectorises a kernel across work items, returns a float3 from an out-of-line function
// of the vectorised kernel one component late, and rounds its vectorised and its scalar code (for
// work groups smaller than its vector width) differently.
#ifdef RC_SCALAR_WORK_ITEMS
#define RC_KERNEL __attribute__((intel_vec_len_hint(1))) __kernel
#else
#define RC_KERNEL __kernel
#endif
#define RC_GLOBAL __global
#define RC_CONSTANT __constant
#define rc_mul_hi(a, b) mul_hi((a), (b))
#define rc_as_uint(x) as_uint(x)
#define rc_as_float(x) as_float(x)
#define rc_as_int(x) as_int(x)
#define rc_offsetof(type, field) __builtin_offsetof(type, field)
#define rc_shuffle(v, mask) shuffle((v), (mask))
// 64-bit integer atomic addition (the irradiance vector grid's fixed-point sums): the
// extension's where the compiler enables cl_khr_int64_base_atomics; elsewhere (Mesa's rusticl
// lists the extension but its compiler does not define it, and atom_add's 64-bit overloads are
// then missing) two 32-bit atomic additions, the low word's carry added to the high word. Integer
// addition commutes, so once the launch ends every slot holds the exact 64-bit sum either way
// (a read during the launch could see a torn value; none happens).
#ifdef cl_khr_int64_base_atomics
#define rc_atomic_add_long(pointer, value) atom_add((pointer), (value))
#else
RC_FUNC void rc_atomic_add_long(__global volatile long* pointer, long value) {
    __global volatile uint* words = (__global volatile uint*)pointer;
#ifdef __ENDIAN_LITTLE__
    const int low_word = 0;
#else
    const int low_word = 1;
#endif
    const uint low = (uint)value;
    const uint high = (uint)((ulong)value >> 32);
    const uint before = atomic_add(&words[low_word], low);
    const uint carry = before + low < before ? 1u : 0u;
    if (high + carry != 0u) {
        atomic_add(&words[1 - low_word], high + carry);
    }
}
#endif
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
