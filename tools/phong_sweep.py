#!/usr/bin/env python3
"""The glossy caches against path tracing over the Phong exponent, at equal time (the
shape of Fig. 4 of the SDRC paper): where does radiance caching (`rc`) stop paying off, and
where does spatial directional radiance caching (`sdrc`) overtake it?

For each exponent, a sphere of Phong exponent E (diffuse 0.1, specular 0.6) filling most of the
view, in a box with a red and a blue wall and a small area light (the sphere's glossy light is
the walls' indirect light), at --size pixels:

  1. a path-traced reference at --reference-spp (kept in OUT and reused when it exists);
  2. for each of --methods: `radcache render --method M` at --spp camera samples (with
     --method-options), its render time T_M from --stats;
  3. `radcache render --method pt --time T_M`: path tracing for the same render time;
  4. every image's relMSE against the reference, of the indirect layer and of the whole image
     (`radcache compare`).

Writes OUT/phong.csv (per exponent: rc's order and fallback fraction, sdrc's hit rate, and per
method its records, T, the pt spp at T and the four errors) and OUT/phong.png (indirect relMSE
against exponent, log-log, each method and pt at its time; rc's fallback fraction on a second
axis). Every figure is a time: run it on an otherwise idle machine.

Usage: tools/phong_sweep.py [--methods rc sdrc] [--exponents 8 16 24 32 64] [--size 128]
           [--spp 8] [--reference-spp 4096] [--method-options "--ic-bounces 1"]
           [--out build/phong] [-- radcache render options for every render, e.g. --device 0:0]
"""

import argparse
import csv
import os
import sys

from radcache_tools import ROOT, radcache
from radcache_tools.arguments import parse_with_extra
from radcache_tools.error import relmse as compared_relmse

METHODS = ["rc", "sdrc"]
PER_METHOD = ["records", "seconds", "pt_spp", "indirect_relmse", "pt_indirect_relmse", "relmse",
              "pt_relmse"]


def columns(methods):
    names = ["exponent", "rc_order", "rc_fallback_fraction", "sdrc_hit_rate"]
    for m in methods:
        names += ["%s_%s" % (m, c) for c in PER_METHOD]
    return names


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


def render(scene, image, options):
    return radcache.render(scene, image, options, tool="phong_sweep", echo=True)


def relmse(image, reference, aov):
    return compared_relmse(image, reference, image[:-len(".exr")] + "." + aov + ".compare.json",
                           aov, tool="phong_sweep", echo=True)


def method_figures(method, stats):
    """The method's own figures from its --stats: records, and rc's order and fallback fraction
    or sdrc's hit rate."""
    frame = stats["frames"][0]
    if method == "rc":
        rc = frame["radiance_cache"]
        return rc["records"], {"rc_order": rc["order"],
                               "rc_fallback_fraction": rc["fallback_fraction"]}
    sdrc = frame["sdrc"]
    return sdrc["records"], {"sdrc_hit_rate": sdrc["hit_rate"]}


def sweep_exponent(exponent, args):
    scene = os.path.join(args.out, "phong-%d.json" % exponent)
    with open(scene, "w") as f:
        f.write(SCENE % {"size": args.size, "exponent": exponent})
    reference = os.path.join(args.out, "reference-%d.exr" % exponent)
    if not os.path.isfile(reference):
        render(scene, reference, ["--method", "pt", "--spp", str(args.reference_spp),
                                  "--aovs", "beauty,direct,indirect"] + args.extra)
    row = {"exponent": exponent, "rc_order": "", "rc_fallback_fraction": "", "sdrc_hit_rate": ""}
    for method in args.methods:
        image = os.path.join(args.out, "%s-%d.exr" % (method, exponent))
        stats = render(scene, image, ["--method", method, "--spp", str(args.spp)] +
                       args.method_options + args.extra)
        seconds = stats["seconds"]["render"]
        pt_image = os.path.join(args.out, "pt-%s-%d.exr" % (method, exponent))
        pt_stats = render(scene, pt_image, ["--method", "pt", "--time", "%.3f" % seconds] +
                          args.extra)
        records, own = method_figures(method, stats)
        row.update(own)
        row.update({"%s_records" % method: records, "%s_seconds" % method: seconds,
                    "%s_pt_spp" % method: pt_stats["frames"][0].get("spp", ""),
                    "%s_indirect_relmse" % method: relmse(image, reference, "indirect"),
                    "%s_pt_indirect_relmse" % method: relmse(pt_image, reference, "indirect"),
                    "%s_relmse" % method: relmse(image, reference, "beauty"),
                    "%s_pt_relmse" % method: relmse(pt_image, reference, "beauty")})
    return row


def chart(rows, methods, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    exponents = [r["exponent"] for r in rows]
    figure, axis = plt.subplots(figsize=(7, 4.5))
    for method, marker in zip(methods, "o^"):
        axis.plot(exponents, [r["%s_indirect_relmse" % method] for r in rows], marker + "-",
                  label="%s, indirect" % method)
        axis.plot(exponents, [r["%s_pt_indirect_relmse" % method] for r in rows], marker + ":",
                  color="grey", label="pt at %s's time, indirect" % method)
    axis.set_xscale("log", base=2)
    axis.set_yscale("log")
    axis.set_xlabel("Phong exponent")
    axis.set_ylabel("relMSE at equal render time")
    lines = axis.get_legend_handles_labels()
    if "rc" in methods:
        second = axis.twinx()
        second.plot(exponents, [r["rc_fallback_fraction"] for r in rows], "k--",
                    label="rc fallback")
        second.set_ylabel("fraction of rc's glossy samples left to Monte Carlo")
        second.set_ylim(-0.02, 1.02)
        more = second.get_legend_handles_labels()
        lines = (lines[0] + more[0], lines[1] + more[1])
    axis.legend(lines[0], lines[1], fontsize=8, loc="upper left")
    figure.tight_layout()
    figure.savefig(path, dpi=110)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--methods", nargs="+", choices=METHODS, default=METHODS)
    parser.add_argument("--exponents", nargs="+", type=int, default=[8, 16, 24, 32, 64])
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--spp", type=int, default=8, help="the methods' camera samples per pixel")
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--method-options", default="",
                        help="more options of the methods' renders, one string "
                             "(\"--ic-bounces 1\")")
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "phong"))
    args, args.extra = parse_with_extra(parser, argv)
    args.method_options = args.method_options.split()
    if min(args.exponents) < 1 or args.size < 1 or args.spp < 1 or args.reference_spp < 1:
        parser.error("exponents, --size, --spp and --reference-spp must be positive")
    os.makedirs(args.out, exist_ok=True)
    rows = [sweep_exponent(e, args) for e in args.exponents]
    with open(os.path.join(args.out, "phong.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns(args.methods))
        writer.writeheader()
        writer.writerows(rows)
    chart(rows, args.methods, os.path.join(args.out, "phong.png"))
    for r in rows:
        line = "Phong %3d:" % r["exponent"]
        for m in args.methods:
            line += " %s %d records %.1f s, indirect relMSE %.3g (pt %.3g), image %.3g (pt %.3g);" % (
                m, r["%s_records" % m], r["%s_seconds" % m], r["%s_indirect_relmse" % m],
                r["%s_pt_indirect_relmse" % m], r["%s_relmse" % m], r["%s_pt_relmse" % m])
        print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
