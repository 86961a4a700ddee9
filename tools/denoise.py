#!/usr/bin/env python3
"""Denoises a radcache EXR with Intel Open Image Denoise (pyoidn): what a user of a path tracer
would do with a noisy image, as a curve of tools/sweep.py --denoise.

Reads the image's beauty (R, G, B) and its `albedo` and `normal` layers, which every radcache
method but normals writes (the first hit's albedo and shading normal, averaged over the pixel's
camera samples), as OIDN's auxiliary inputs, runs OIDN's `RT` filter (hdr, quality high, the
auxiliary images taken as noisy: they are averaged like the beauty, not prefiltered) and writes
OUT.exr: the same size and every layer of IN, the beauty replaced by the denoised one (float
channels, IN's compression). EXRs are read and written with the OpenEXR package. A missing
auxiliary layer is one error line naming it (exit status 1); so is a missing pyoidn or OpenEXR.

Usage: tools/denoise.py IN.exr OUT.exr [--quality high|balanced|fast]
As a library: denoise_file(IN, OUT) returns the seconds of the OIDN filter alone.
"""

import argparse
import os
import sys
import time

import numpy

AUXILIARY = ("albedo", "normal")


class DenoiseError(Exception):
    """A denoise that cannot be done: one line."""


def available():
    """Whether pyoidn and OpenEXR can be imported."""
    try:
        import OpenEXR  # noqa: F401
        import pyoidn  # noqa: F401
    except ImportError:
        return False
    return True


def read_exr(image):
    """Every channel of an EXR as float32 arrays, by name, and its header."""
    import OpenEXR
    try:
        with OpenEXR.File(image, separate_channels=True) as f:
            header = dict(f.header())
            pixels = {name: numpy.asarray(c.pixels, dtype=numpy.float32)
                      for name, c in f.channels().items()}
    except Exception as e:  # OpenEXR raises plain exceptions for unreadable files
        raise DenoiseError("%s: cannot read it as OpenEXR (%s)" % (image, e))
    return pixels, header


def layer(image, pixels, name):
    """A layer's R, G, B ("" for the beauty) as one (H, W, 3) array, or DenoiseError naming it."""
    wanted = [(name + "." if name else "") + c for c in ("R", "G", "B")]
    missing = [w for w in wanted if w not in pixels]
    if missing:
        raise DenoiseError("%s has no %s layer (missing %s): render it with that layer (--aovs)"
                           % (image, name or "beauty", ", ".join(missing)))
    return numpy.ascontiguousarray(numpy.stack([pixels[w] for w in wanted], axis=-1))


def write_exr(target, pixels, header):
    """An EXR of these float32 channels, written beside TARGET first and then moved in place."""
    import OpenEXR
    kept = {k: header[k] for k in ("compression", "pixelAspectRatio", "screenWindowCenter",
                                   "screenWindowWidth") if k in header}
    kept["type"] = OpenEXR.scanlineimage
    partial = target + ".partial.exr"
    with OpenEXR.File(kept, pixels) as f:
        f.write(partial)
    os.replace(partial, target)


def denoise_arrays(arrays, quality="high"):
    """OIDN over the beauty with albedo and normal; returns (denoised, seconds of the filter)."""
    import pyoidn
    start = time.perf_counter()
    result = pyoidn.denoise(arrays["beauty"], arrays["albedo"], arrays["normal"], hdr=True,
                            quality=quality)
    return numpy.asarray(result, dtype=numpy.float32), time.perf_counter() - start


def denoise_file(source, target, quality="high"):
    """Denoises SOURCE.exr into TARGET.exr (every other layer kept); the filter's seconds."""
    if not available():
        raise DenoiseError("pyoidn and OpenEXR are needed (python3 -m pip install pyoidn "
                           "OpenEXR)")
    pixels, header = read_exr(source)
    arrays = {name or "beauty": layer(source, pixels, name) for name in ("",) + AUXILIARY}
    denoised, seconds = denoise_arrays(arrays, quality)
    for index, channel in enumerate(("R", "G", "B")):
        pixels[channel] = numpy.ascontiguousarray(denoised[..., index])
    write_exr(target, pixels, header)
    return seconds


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("input", help="a radcache EXR with albedo and normal layers")
    parser.add_argument("output", help="the denoised EXR")
    parser.add_argument("--quality", choices=["high", "balanced", "fast"], default="high")
    args = parser.parse_args(argv)
    if not os.path.isfile(args.input):
        parser.error("no such image: %s" % args.input)
    if os.path.exists(args.output) and os.path.samefile(args.input, args.output):
        print("denoise: the output %s is the input: name another file" % args.output,
              file=sys.stderr)
        sys.exit(2)
    try:
        seconds = denoise_file(args.input, args.output, args.quality)
    except DenoiseError as e:
        sys.exit("denoise: %s" % e)
    print("denoised %s -> %s (OIDN filter %.3f s)" % (args.input, args.output, seconds))


if __name__ == "__main__":
    main(sys.argv[1:])
