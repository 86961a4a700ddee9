// Counter-based random numbers: Philox4x32-10 (Salmon, Moraes, Dror, Shaw, "Parallel Random
// Numbers: As Easy as 1, 2, 3", SC 2011). Stateless: every value is a function of
// (seed, stream, sample, dimension), so results never depend on thread order or chunking.
// The same code runs on the host (C++) and on the device (OpenCL C).
#pragma once

#include "compat.h"

RC_SHARED_BEGIN

// One Philox4x32 block: 10 rounds over the counter (c0..c3) with the key (k0, k1).
RC_FUNC void rc_philox4x32_10(uint c0, uint c1, uint c2, uint c3, uint k0, uint k1, uint* out) {
    for (int round = 0; round < 10; ++round) {
        const uint hi0 = rc_mul_hi(0xD2511F53u, c0);
        const uint lo0 = 0xD2511F53u * c0;
        const uint hi1 = rc_mul_hi(0xCD9E8D57u, c2);
        const uint lo1 = 0xCD9E8D57u * c2;
        c0 = hi1 ^ c1 ^ k0;
        c1 = lo1;
        c2 = hi0 ^ c3 ^ k1;
        c3 = lo0;
        k0 += 0x9E3779B9u;  // Weyl key schedule
        k1 += 0xBB67AE85u;
    }
    out[0] = c0;
    out[1] = c1;
    out[2] = c2;
    out[3] = c3;
}

// A stream of random numbers for one (seed, stream, sample): `stream` is a pixel, record or
// photon index, `sample` the sample index. Dimension d is word d % 4 of block d / 4.
typedef struct RngStream {
    uint key0, key1;
    uint stream, sample;
    uint dimension;
    uint block[4];
} RngStream;

RC_FUNC RngStream rc_rng_stream(uint seed_lo, uint seed_hi, uint stream, uint sample) {
    RngStream s;
    s.key0 = seed_lo;
    s.key1 = seed_hi;
    s.stream = stream;
    s.sample = sample;
    s.dimension = 0;
    s.block[0] = s.block[1] = s.block[2] = s.block[3] = 0;
    return s;
}

// The 32-bit word at `dimension` of (seed, stream, sample), independent of any other call.
RC_FUNC uint rc_rng_word(uint seed_lo, uint seed_hi, uint stream, uint sample, uint dimension) {
    uint block[4];
    rc_philox4x32_10(stream, sample, dimension >> 2, 0x52434348u, seed_lo, seed_hi, block);
    return block[dimension & 3u];
}

// The next word of the stream.
RC_FUNC uint rc_rng_next_uint(RngStream* s) {
    const uint lane = s->dimension & 3u;
    if (lane == 0u) {
        rc_philox4x32_10(s->stream, s->sample, s->dimension >> 2, 0x52434348u, s->key0, s->key1,
                         s->block);
    }
    s->dimension += 1u;
    return s->block[lane];
}

// Uniform float in [0, 1): the top 24 bits scaled by 2^-24, so 1.0f is never returned.
RC_FUNC float rc_uint_to_unit_float(uint word) { return (float)(word >> 8) * (1.0f / 16777216.0f); }

RC_FUNC float rc_rng_next_float(RngStream* s) { return rc_uint_to_unit_float(rc_rng_next_uint(s)); }

RC_SHARED_END
