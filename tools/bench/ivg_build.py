#!/usr/bin/env python3
"""Irradiance vector grid build time against resolution and photon count.

For each scene, grid resolution and photon count: one `radcache render --method ivg` at 32 x 32
pixels (the render pass is negligible) with --stats; reports the photon-tracing and
normalisation seconds, photons/s, face crossings per photon and the grid's memory, and the
indirect relMSE of a 512 x 512 `ivg` render at 4 samples per pixel against the scene's
reference when --accuracy is given. Kernel binaries are warmed first. Standard library only.

Usage: tools/bench/ivg_build.py [--scenes cornell-box two-rooms] [--grids 16x16x16 auto 64x64x64]
           [--photons 65536 262144 1048576] [--accuracy] [--out build/bench/ivg]
"""

import argparse
import json
import os

from radcache_tools import ROOT
from radcache_tools import references
from radcache_tools import radcache
from radcache_tools.error import relmse
from radcache_tools.radcache import run


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", nargs="+", default=["cornell-box", "two-rooms"])
    parser.add_argument("--grids", nargs="+", default=["16x16x16", "auto", "64x64x64"])
    parser.add_argument("--photons", nargs="+", default=["65536", "262144", "1048576"])
    parser.add_argument("--accuracy", action="store_true",
                        help="also render 512 x 512 and measure the indirect relMSE")
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "ivg"))
    args = parser.parse_args()
    radcache.require_built()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for scene_name in args.scenes:
        scene = os.path.join(ROOT, "scenes", scene_name, "scene.json")
        warm = os.path.join(args.out, "warm.exr")
        run(["render", scene, "-o", warm, "--method", "ivg", "--photons", "1000", "--width",
             "16", "--height", "16", "--spp", "1", "--quiet"])
        for grid in args.grids:
            for photons in args.photons:
                image = os.path.join(args.out, "%s-%s-%s.exr" % (scene_name, grid, photons))
                stats_path = image + ".json"
                size = ["--width", "512", "--height", "512", "--spp", "4"] if args.accuracy \
                    else ["--width", "32", "--height", "32", "--spp", "1"]
                run(["render", scene, "-o", image, "--method", "ivg", "--grid", grid,
                     "--photons", photons, "--stats", stats_path, "--quiet"] + size)
                with open(stats_path) as f:
                    g = json.load(f)["frames"][0]["grid"]
                row = {"scene": scene_name, "grid": "x".join(str(c) for c in g["cells"]),
                       "photons": g["photons"], "photon_seconds": g["seconds"]["photons"],
                       "normalize_seconds": g["seconds"]["normalize"],
                       "photons_per_second": g["photons_per_second"],
                       "crossings_per_photon": g["crossings"] / max(g["photons"], 1),
                       "grid_mib": g["grid_bytes"] / 2.0 ** 20}
                if args.accuracy:
                    # The reference of the frame a render without --frames shows.
                    reference = references.reference_path(os.path.join(ROOT, "scenes",
                                                                       scene_name))
                    row["indirect_relmse"] = relmse(image, reference, image + ".compare.json",
                                                    "indirect")
                rows.append(row)
                print(json.dumps(row), flush=True)
    with open(os.path.join(args.out, "ivg_build.json"), "w") as f:
        json.dump({"device": run(["devices"]).strip(), "rows": rows}, f, indent=2)
    print("%-12s %-10s %9s %9s %9s %10s %9s %9s %s" % (
        "scene", "grid", "photons", "trace s", "norm s", "photons/s", "cross/ph", "MiB",
        "indirect relMSE" if args.accuracy else ""))
    for r in rows:
        print("%-12s %-10s %9d %9.2f %9.3f %10.0f %9.1f %9.2f %s" % (
            r["scene"], r["grid"], r["photons"], r["photon_seconds"], r["normalize_seconds"],
            r["photons_per_second"], r["crossings_per_photon"], r["grid_mib"],
            "%.4g" % r["indirect_relmse"] if "indirect_relmse" in r else ""))


if __name__ == "__main__":
    main()
