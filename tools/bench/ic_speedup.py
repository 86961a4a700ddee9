#!/usr/bin/env python3
"""Equal-quality speed-up of irradiance caching over path tracing (its target: ≥ 20× at default accuracy).

For each scene: renders `--method ic` at its default settings for each camera sample count
given, measures its error against the scene's reference (relMSE of the beauty and of the
indirect layer), then finds the time the path tracer needs to reach the same error: one path
traced run to --pt-spp samples per pixel writes its image at every power of two
(--save-every-pow2); the time at N samples is the run's render time times N / total (a pass
costs the same whatever its index); the samples needed are interpolated log-log between the
powers of two that bracket the target. Both methods run side by side in this one invocation,
on the same device, with kernel binaries warm (one untimed render of each first). Times are the
render phase of `--stats` (scene loading, device start and image writing excluded).

Usage: tools/bench/ic_speedup.py [--scenes cornell-box two-rooms] [--ic-spp 4 16 64]
           [--pt-spp 4096] [--out build/bench/ic] [-- extra radcache render options]
Writes OUT/ic_speedup.json and prints a table. Python 3 standard library only.
"""

import argparse
import json
import math
import os
import sys

from radcache_tools import ROOT
from radcache_tools import references
from radcache_tools import radcache
from radcache_tools.error import relmse
from radcache_tools.radcache import run


def spp_for(target, curve):
    """Samples per pixel at which a (spp, relMSE) curve, decreasing, reaches `target`:
    log-log interpolation between the bracketing points; None beyond the last."""
    for (n0, e0), (n1, e1) in zip(curve, curve[1:]):
        if e0 >= target >= e1:
            if e0 == e1:
                return n0
            t = (math.log(e0) - math.log(target)) / (math.log(e0) - math.log(e1))
            return math.exp(math.log(n0) + t * (math.log(n1) - math.log(n0)))
    if curve and target >= curve[0][1]:
        return curve[0][0]
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", nargs="+", default=["cornell-box", "two-rooms"])
    parser.add_argument("--ic-spp", nargs="+", type=int, default=[4, 16, 64])
    parser.add_argument("--pt-spp", type=int, default=4096)
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "ic"))
    parser.add_argument("extra", nargs="*", help="more radcache render options (after --)")
    args = parser.parse_args()
    radcache.require_built()
    if args.pt_spp & (args.pt_spp - 1):
        sys.exit("--pt-spp must be a power of two")
    os.makedirs(args.out, exist_ok=True)
    device = run(["devices"]).strip()
    results = []
    for name in args.scenes:
        scene = os.path.join(ROOT, "scenes", name, "scene.json")
        # The reference of the frame a render without --frames shows (scenes/README.md).
        reference = references.reference_path(os.path.join(ROOT, "scenes", name))
        out = os.path.join(args.out, name)
        os.makedirs(out, exist_ok=True)
        # Warm the kernel binary cache for both methods.
        for method in ("pt", "ic"):
            radcache.render(scene, os.path.join(out, "warm.exr"),
                            ["--method", method, "--width", "16", "--height", "16", "--spp", "1"]
                            + args.extra, os.path.join(out, "warm.json"))

        pt_image = os.path.join(out, "pt.exr")
        pt_stats = radcache.render(scene, pt_image, ["--method", "pt", "--spp", str(args.pt_spp),
                                                     "--save-every-pow2"] + args.extra,
                                   os.path.join(out, "pt.json"))
        pt_seconds = pt_stats["seconds"]["render"]
        curves = {"beauty": [], "indirect": []}
        n = 1
        while n <= args.pt_spp:
            image = pt_image if n == args.pt_spp else os.path.join(out, "pt.spp%d.exr" % n)
            for aov in curves:
                curves[aov].append(
                    (n, relmse(image, reference, os.path.join(out, "pt-%d-%s.json" % (n, aov)), aov)))
            n *= 2

        for spp in args.ic_spp:
            image = os.path.join(out, "ic-%d.exr" % spp)
            stats = radcache.render(scene, image, ["--method", "ic", "--spp", str(spp)] +
                                    args.extra, os.path.join(out, "ic-%d.json" % spp))
            ic_seconds = stats["seconds"]["render"]
            row = {"scene": name, "ic_spp": spp, "ic_seconds": ic_seconds,
                   "records": stats["frames"][0]["records"], "pt_seconds_per_spp":
                   pt_seconds / args.pt_spp}
            for aov, curve in curves.items():
                error = relmse(image, reference, os.path.join(out, "ic-%d-%s.json" % (spp, aov)), aov)
                needed = spp_for(error, curve)
                row[aov] = {
                    "ic_relmse": error,
                    "pt_spp": needed,
                    "pt_seconds": None if needed is None else needed * pt_seconds / args.pt_spp,
                    "speedup": None if needed is None else
                    needed * pt_seconds / args.pt_spp / ic_seconds,
                    "speedup_at_least": (args.pt_spp * pt_seconds / args.pt_spp / ic_seconds
                                         if needed is None else None),
                }
            results.append(row)
        for aov, curve in curves.items():
            results.append({"scene": name, "pt_curve": aov, "points": curve})

    report = {"device": device, "pt_spp": args.pt_spp, "results": results,
              "command": " ".join([os.path.relpath(sys.argv[0], ROOT)] + sys.argv[1:])}
    with open(os.path.join(args.out, "ic_speedup.json"), "w") as f:
        json.dump(report, f, indent=2)
    print("%-12s %6s %8s %8s | %-8s %10s %9s %9s %8s" % (
        "scene", "ic spp", "records", "ic s", "layer", "ic relMSE", "pt spp", "pt s", "speed-up"))
    for row in results:
        if "ic_spp" not in row:
            continue
        for aov in ("beauty", "indirect"):
            r = row[aov]
            if r["pt_spp"] is None:
                needed, seconds = "> %d" % args.pt_spp, "> %.1f" % (args.pt_spp * row["pt_seconds_per_spp"])
                speedup = "> %.1f" % r["speedup_at_least"]
            else:
                needed, seconds, speedup = "%.0f" % r["pt_spp"], "%.1f" % r["pt_seconds"], "%.1f" % r["speedup"]
            print("%-12s %6d %8d %8.2f | %-8s %10.3g %9s %9s %8s" % (
                row["scene"], row["ic_spp"], row["records"], row["ic_seconds"], aov,
                r["ic_relmse"], needed, seconds, speedup))
    print("written to %s" % os.path.join(args.out, "ic_speedup.json"))


if __name__ == "__main__":
    main()
