#!/usr/bin/env python3
"""Radiance caching against path tracing over the Phong exponent, at equal time (issue 11; the
shape of Fig. 4 of the SDRC paper): where does `rc` stop paying off, and does the adaptive order
move the lobe to Monte Carlo there?

For each exponent, a sphere of Phong exponent E (diffuse 0.1, specular 0.6) filling most of the
view, in a box with a red and a blue wall and a small area light (the sphere's glossy light is
the walls' indirect light), at --size pixels:

  1. a path-traced reference at --reference-spp (kept in OUT and reused when it exists);
  2. `radcache render --method rc` at --spp camera samples (its other options at their
     defaults), its render time T from --stats;
  3. `radcache render --method pt --time T`: path tracing for the same render time;
  4. both images' relMSE against the reference, of the indirect layer and of the whole image
     (`radcache compare`).

Writes OUT/phong.csv (exponent, order, fallback fraction, records, T, pt spp, the four errors)
and OUT/phong.png (relMSE against exponent, log-log, rc and pt, indirect and image; the
fallback fraction on a second axis). Every figure is a time: run it on an otherwise idle machine.

Usage: tools/rc_phong_sweep.py [--exponents 8 16 32 64] [--size 128] [--spp 8]
           [--reference-spp 4096] [--rc-options "--ic-bounces 1"] [--out build/rc-phong]
           [-- radcache render options for every render, e.g. --device 0:0]
"""

import argparse
import csv
import json
import os
import subprocess
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")
COLUMNS = ["exponent", "order", "fallback_fraction", "rc_records", "rc_seconds", "pt_spp",
           "pt_seconds", "rc_indirect_relmse", "pt_indirect_relmse", "rc_relmse", "pt_relmse"]

SCENE = """{
    "camera": {"position": [0, -0.1, -2.2], "look_at": [0, -0.5, 0], "up": [0, 1, 0],
               "fov": 30, "resolution": [%(size)d, %(size)d]},
    "materials": {
        "white": {"type": "diffuse", "reflectance": 0.5},
        "red": {"type": "diffuse", "reflectance": [0.7, 0.1, 0.1]},
        "blue": {"type": "diffuse", "reflectance": [0.1, 0.15, 0.7]},
        "sphere": {"type": "phong", "diffuse": 0.1, "specular": 0.6, "exponent": %(exponent)d}},
    "shapes": [
        {"type": "rectangle", "material": "white",
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"translate": [0, -1, 0]}]},
        {"type": "rectangle", "material": "white",
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}}, {"translate": [0, 1, 0]}]},
        {"type": "rectangle", "material": "white",
         "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 180}}, {"translate": [0, 0, 1]}]},
        {"type": "rectangle", "material": "red",
         "transform": [{"rotate": {"axis": [0, 1, 0], "angle": -90}}, {"translate": [1, 0, 0]}]},
        {"type": "rectangle", "material": "blue",
         "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 90}}, {"translate": [-1, 0, 0]}]},
        {"type": "rectangle", "material": "white", "emitter": {"type": "area", "radiance": 12},
         "transform": [{"scale": 0.3}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                       {"translate": [0, 0.998, 0]}]},
        {"type": "sphere", "center": [0, -0.55, 0], "radius": 0.45, "material": "sphere"}
    ]
}
"""


def run(command):
    print("+ " + " ".join(command), flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("rc_phong_sweep: %s failed:\n%s%s" % (" ".join(command), result.stdout,
                                                        result.stderr))
    return result.stdout


def render(scene, image, options):
    stats_path = image[:-len(".exr")] + ".stats.json"
    run([RADCACHE, "render", scene, "-o", image, "--stats", stats_path, "--quiet"] + options)
    with open(stats_path) as f:
        return json.load(f)


def relmse(image, reference, aov):
    figures = image[:-len(".exr")] + "." + aov + ".compare.json"
    run([RADCACHE, "compare", image, reference, "--aov", aov, "--json", figures])
    with open(figures) as f:
        return json.load(f)["relmse"]


def sweep_exponent(exponent, args):
    scene = os.path.join(args.out, "phong-%d.json" % exponent)
    with open(scene, "w") as f:
        f.write(SCENE % {"size": args.size, "exponent": exponent})
    reference = os.path.join(args.out, "reference-%d.exr" % exponent)
    if not os.path.isfile(reference):
        render(scene, reference, ["--method", "pt", "--spp", str(args.reference_spp),
                                  "--aovs", "beauty,direct,indirect"] + args.extra)
    rc_image = os.path.join(args.out, "rc-%d.exr" % exponent)
    rc_stats = render(scene, rc_image, ["--method", "rc", "--spp", str(args.spp)] +
                      args.rc_options + args.extra)
    seconds = rc_stats["seconds"]["render"]
    pt_image = os.path.join(args.out, "pt-%d.exr" % exponent)
    pt_stats = render(scene, pt_image, ["--method", "pt", "--time", "%.3f" % seconds] +
                      args.extra)
    frame = rc_stats["frames"][0]["radiance_cache"]
    return {"exponent": exponent, "order": frame["order"],
            "fallback_fraction": frame["fallback_fraction"], "rc_records": frame["records"],
            "rc_seconds": seconds, "pt_spp": pt_stats["frames"][0].get("spp", ""),
            "pt_seconds": pt_stats["seconds"]["render"],
            "rc_indirect_relmse": relmse(rc_image, reference, "indirect"),
            "pt_indirect_relmse": relmse(pt_image, reference, "indirect"),
            "rc_relmse": relmse(rc_image, reference, "beauty"),
            "pt_relmse": relmse(pt_image, reference, "beauty")}


def chart(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    exponents = [r["exponent"] for r in rows]
    figure, axis = plt.subplots(figsize=(7, 4.5))
    for key, label, style in (("rc_indirect_relmse", "rc, indirect", "o-"),
                              ("pt_indirect_relmse", "pt, indirect", "s-"),
                              ("rc_relmse", "rc, image", "o--"),
                              ("pt_relmse", "pt, image", "s--")):
        axis.plot(exponents, [r[key] for r in rows], style, label=label)
    axis.set_xscale("log", base=2)
    axis.set_yscale("log")
    axis.set_xlabel("Phong exponent")
    axis.set_ylabel("relMSE at equal render time")
    second = axis.twinx()
    second.plot(exponents, [r["fallback_fraction"] for r in rows], "k:", label="rc fallback")
    second.set_ylabel("fraction of the sphere's samples left to Monte Carlo")
    second.set_ylim(-0.02, 1.02)
    lines = axis.get_legend_handles_labels()
    more = second.get_legend_handles_labels()
    axis.legend(lines[0] + more[0], lines[1] + more[1], fontsize=8, loc="upper left")
    figure.tight_layout()
    figure.savefig(path, dpi=110)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--exponents", nargs="+", type=int, default=[8, 16, 32, 64])
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--spp", type=int, default=8, help="rc's camera samples per pixel")
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--rc-options", default="",
                        help="more options of the rc renders, one string (\"--ic-bounces 1\")")
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "rc-phong"))
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    args = parser.parse_args(argv)
    args.extra = extra
    args.rc_options = args.rc_options.split()
    if min(args.exponents) < 1 or args.size < 1 or args.spp < 1 or args.reference_spp < 1:
        parser.error("exponents, --size, --spp and --reference-spp must be positive")
    os.makedirs(args.out, exist_ok=True)
    rows = [sweep_exponent(e, args) for e in args.exponents]
    with open(os.path.join(args.out, "phong.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    chart(rows, os.path.join(args.out, "phong.png"))
    for r in rows:
        print("Phong %3d: order %d, fallback %.2f, %d records, %.1f s (pt %s spp); indirect "
              "relMSE rc %.3g pt %.3g (%.1fx); image rc %.3g pt %.3g (%.1fx)" % (
                  r["exponent"], r["order"], r["fallback_fraction"], r["rc_records"],
                  r["rc_seconds"], r["pt_spp"], r["rc_indirect_relmse"],
                  r["pt_indirect_relmse"], r["pt_indirect_relmse"] / r["rc_indirect_relmse"],
                  r["rc_relmse"], r["pt_relmse"], r["pt_relmse"] / r["rc_relmse"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
