#!/usr/bin/env python3
"""Renders a radcache scene with Mitsuba 3's path tracer (the Mitsuba peer): one image.

Exports the scene (tools/peers/mitsuba/export.py: only what has an exact counterpart; anything
else is refused with one line naming it, exit status 1), renders it at --spp samples per pixel
with the scene's max depth, and writes OUT.exr (R, G, B: radcache compare reads it as the beauty
layer) and OUT.json: spp, variant, threads, load_seconds (export and mi.load_dict),
render_seconds (mi.render alone, the JIT compilation of an LLVM variant included) and the
Mitsuba version. The whole process's wall time is measured by the caller (ladder.py).

Usage: tools/peers/mitsuba/render.py SCENE OUT.exr [--spp N] [--width W --height H]
           [--variant scalar_rgb|llvm_ad_rgb] [--seed N]
SCENE is a scene directory or its scene.json.
"""

import argparse
import json
import os
import sys
import time

from radcache_tools.arguments import positive_int
import export

VARIANTS = ["scalar_rgb", "llvm_ad_rgb"]


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene", help="scene directory or scene.json")
    parser.add_argument("output", help="the image, .exr")
    parser.add_argument("--spp", type=positive_int, help="samples per pixel (default: the scene's)")
    parser.add_argument("--width", type=positive_int)
    parser.add_argument("--height", type=positive_int)
    parser.add_argument("--variant", choices=VARIANTS, default="scalar_rgb")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    if os.path.isdir(args.scene):
        args.scene = os.path.join(args.scene, "scene.json")
    if not os.path.isfile(args.scene):
        parser.error("scene not found: %s" % args.scene)
    if not args.output.endswith(".exr"):
        parser.error("the output must be an .exr: %s" % args.output)
    return args


def load_mitsuba(variant):
    try:
        import mitsuba as mi
    except ImportError:
        sys.exit("mitsuba peer: the mitsuba package is not installed (python3 -m pip install "
                 "mitsuba)")
    mi.set_variant(variant)
    return mi


def main(argv):
    args = parse_arguments(argv)
    mi = load_mitsuba(args.variant)
    start = time.perf_counter()
    try:
        scene = mi.load_dict(export.scene_dict(args.scene, args.width, args.height, args.spp))
    except export.ExportError as e:
        sys.exit("mitsuba peer: %s: %s" % (args.scene, e))
    loaded = time.perf_counter()
    image = mi.render(scene, seed=args.seed)
    partial = args.output + ".partial.exr"
    mi.Bitmap(image, channel_names=["R", "G", "B"]).write(partial)
    os.replace(partial, args.output)
    rendered = time.perf_counter()
    import drjit as dr
    record = {"spp": scene.sensors()[0].sampler().sample_count(), "variant": args.variant,
              "threads": dr.thread_count(), "mitsuba": mi.__version__,
              "load_seconds": loaded - start, "render_seconds": rendered - loaded}
    with open(os.path.splitext(args.output)[0] + ".json", "w") as f:
        json.dump(record, f, indent=2)


if __name__ == "__main__":
    main(sys.argv[1:])
