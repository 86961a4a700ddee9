// Test kernels (tests/shared/rng_test.cpp): the device's counter-based RNG, for comparison with the
// host.
#include "common/kernel_range.h"
#include "shared/rng.h"

// Philox4x32-10 of the counter and key in inputs[6i .. 6i+5] into outputs[4i .. 4i+3].
RC_KERNEL void philox_blocks(uint begin, uint end, __global const uint* inputs,
                             __global uint* outputs) {
    RC_RANGE_ITEM(i);
    uint block[4];
    __global const uint* in = inputs + 6 * i;
    rc_philox4x32_10(in[0], in[1], in[2], in[3], in[4], in[5], block);
    for (int k = 0; k < 4; ++k) {
        outputs[4 * i + k] = block[k];
    }
}

// The first `dimensions` words of stream i (sample `sample`) into out[i * dimensions + d].
RC_KERNEL void rng_stream_words(uint begin, uint end, uint seed_lo, uint seed_hi, uint sample,
                                uint dimensions, __global uint* out) {
    RC_RANGE_ITEM(i);
    RngStream rng = rc_rng_stream(seed_lo, seed_hi, i, sample);
    for (uint d = 0; d < dimensions; ++d) {
        out[i * dimensions + d] = rc_rng_next_uint(&rng);
    }
}
