#!/usr/bin/env python3
"""The Mitsuba peer over a ladder of samples per pixel: one process of render.py per point.

For each --spp N runs tools/peers/mitsuba/render.py SCENE OUT/spp-N.exr --spp N as its own
process, times it with the wall clock (python start-up, import of Mitsuba, export, scene
loading, render and writing: what a user waits for), and writes OUT/mitsuba.csv: setting, spp,
wall_seconds (the whole process), render_seconds (mi.render alone, from render.py's record),
load_seconds, variant, threads, mitsuba (its version), image. A scene the exporter refuses
stops the ladder with render.py's one line and exit status 1.

Usage: tools/peers/mitsuba/ladder.py SCENE [--spp 4 16 64 ...] [--out DIR] [--width W
           --height H] [--variant scalar_rgb|llvm_ad_rgb]
"""

import argparse
import csv
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
from radcache_tools.arguments import positive_int

COLUMNS = ["setting", "spp", "wall_seconds", "render_seconds", "load_seconds", "variant",
           "threads", "mitsuba", "image"]


def render_point(scene, image, spp, options):
    """One render.py process; its record with wall_seconds added."""
    command = [sys.executable, os.path.join(HERE, "render.py"), scene, image, "--spp", str(spp)]
    start = time.perf_counter()
    result = subprocess.run(command + options, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if result.returncode != 0:
        sys.exit(result.stderr.strip().splitlines()[-1] if result.stderr.strip() else
                 "mitsuba peer: render.py failed at %d spp" % spp)
    with open(os.path.splitext(image)[0] + ".json") as f:
        record = json.load(f)
    return dict(record, wall_seconds=wall, setting="spp=%d" % spp, image=image)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene", help="scene directory or scene.json")
    parser.add_argument("--spp", nargs="+", type=positive_int, default=[4, 16, 64, 256])
    parser.add_argument("--out", default="build/peers/mitsuba")
    parser.add_argument("--width", type=positive_int)
    parser.add_argument("--height", type=positive_int)
    parser.add_argument("--variant", choices=["scalar_rgb", "llvm_ad_rgb"], default="scalar_rgb")
    args = parser.parse_args(argv)
    options = ["--variant", args.variant]
    for name in ("width", "height"):
        if getattr(args, name):
            options += ["--" + name, str(getattr(args, name))]
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for spp in args.spp:
        image = os.path.join(os.path.abspath(args.out), "spp-%d.exr" % spp)
        rows.append(render_point(args.scene, image, spp, options))
        print("mitsuba %s: %.3f s (render %.3f s)" % (rows[-1]["setting"],
              rows[-1]["wall_seconds"], rows[-1]["render_seconds"]), flush=True)
    with open(os.path.join(args.out, "mitsuba.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main(sys.argv[1:])
