"""The standalone reproducer of Intel's CPU OpenCL compiler returning a float3 one component late.

A function the compiler keeps out of line (here by `noinline`; in radcache's kernels by its own
choice) and vectorises across work items returns (x, y, z) to its caller as (?, x, y). The same
function returning a float4 is right, and so is every build with -cl-opt-disable or a kernel
declared __attribute__((intel_vec_len_hint(1))) (compiled one work item at a time). Found in
Intel's CPU runtime 2026.2 (intel-opencl-rt from pip), on AMD EPYC and Intel Xeon processors;
radcache compiles every kernel one work item at a time there (host/device/compiler_workarounds.cpp,
docs/devices.md "Compiler workarounds").

Runs the kernel on every OpenCL device it finds, with and without -cl-opt-disable, and prints each
one's count of wrong work items; exits 1 when a device answers wrong. Needs pyopencl
(tools/requirements-peers.txt); for Intel's runtime:

    tools/intel-opencl.sh run python3 tools/intel_float3_repro.py
"""

import sys

import numpy as np

SOURCE = r"""
__attribute__((noinline)) float3 make(float a, float b, float c) {
    return (float3)(a, b, c);
}
kernel void probe(global float* out) {
    const int i = get_global_id(0);
    vstore3(make(1.0f, 2.0f, (float)i + 0.5f), i, out);
}
"""
ITEMS = 64


def wrong_items(cl, device, options):
    """The work items whose float3 differs from (1, 2, i + 0.5), and item 1's answer."""
    context = cl.Context([device])
    queue = cl.CommandQueue(context)
    program = cl.Program(context, SOURCE).build(options=options)
    out = np.zeros(3 * ITEMS, np.float32)
    buffer = cl.Buffer(context, cl.mem_flags.WRITE_ONLY, out.nbytes)
    program.probe(queue, (ITEMS,), None, buffer)
    cl.enqueue_copy(queue, out, buffer)
    got = out.reshape(ITEMS, 3)
    index = np.arange(ITEMS, dtype=np.float32)
    expected = np.stack([np.ones(ITEMS), 2 * np.ones(ITEMS), index + 0.5], axis=1)
    return int(np.sum(np.any(got != expected, axis=1))), got[1].tolist()


def main():
    try:
        import pyopencl as cl
    except ImportError:
        print("intel_float3_repro: needs pyopencl (pip install pyopencl)", file=sys.stderr)
        return 2
    any_wrong = False
    for platform in cl.get_platforms():
        for device in platform.get_devices():
            for options in ([], ["-cl-opt-disable"]):
                wrong, item = wrong_items(cl, device, options)
                any_wrong |= wrong > 0
                label = " ".join(options) or "(default)"
                print(f"{platform.name:28s} {label:16s} wrong work items {wrong}/{ITEMS}"
                      f"  item 1: {item} (expected [1.0, 2.0, 1.5])")
    return 1 if any_wrong else 0


if __name__ == "__main__":
    sys.exit(main())
