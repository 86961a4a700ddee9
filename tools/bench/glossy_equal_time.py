#!/usr/bin/env python3
"""The glossy caches against each other and against path tracing at equal time (SDRC's
targets: on the kettle, `sdrc`'s relMSE of the image and of the glossy pixels' indirect light
below `rc`'s and `pt`'s at `sdrc`'s render time).

On one scene (default scenes/kettle), all in this one invocation on one device with warm kernel
binaries (one untimed small render of each method first). The clock (--clock): `wall`, the render
phase of `--stats` (scene loading, device start and image writing excluded), for an otherwise idle
machine; or `cpu` (the default), the CPU seconds (user + system) of the whole radcache process,
which other processes on a shared machine barely change (PoCL's threads are counted; the process's
set-up, about 0.1 s, too):

  1. `sdrc` at its defaults (the scene's spp): its time T and errors.
  2. `rc` at its defaults, then at the camera-sample count its first time predicts for T: its
     errors at T interpolated log-log in time between the run just below T and the run just
     above; when no run brackets T, the nearest run's errors scaled by its time over T (the
     Monte Carlo rate 1/time: generous to `rc` when its run was faster than T), and then said so.
  3. `pt` with --save-every-pow2 up to --pt-spp: its errors at T interpolated log-log between
     the powers of two that bracket T (a pass costs the same whatever its index, so the time of
     N samples is the run's time times N / total).

Errors against the scene's reference (`radcache compare`): relMSE of the beauty layer (and net
of the reference's noise), and relMSE of the indirect layer over the glossy pixels: those where
`sdrc`'s `sdrc-hits` layer is positive (the pixels whose camera samples have a specular lobe
SDRC serves), through `compare --mask`.

Usage: tools/bench/glossy_equal_time.py [--scene scenes/kettle] [--pt-spp 1024] [--clock cpu]
           [--sdrc-options "--sdrc-interp 8"] [--rc-options "--ic-bounces 1"]
           [--out build/bench/glossy]
           [-- extra radcache render options for every render, e.g. --device 0:0]
Writes OUT/glossy_equal_time.json and prints a table. Python 3 standard library only.
"""

import argparse
import json
import math
import os
import shlex
import sys

from radcache_tools import ROOT
from radcache_tools import references
from radcache_tools.arguments import parse_with_extra
from radcache_tools.error import compare
from radcache_tools.radcache import cpu_seconds, run


def render(scene, output, options):
    """The render's --stats, with "cpu_seconds": its process's CPU time."""
    stats = os.path.splitext(output)[0] + ".stats.json"
    before = cpu_seconds()
    run(["render", scene, "-o", output, "--stats", stats, "--quiet"] + options)
    cpu = cpu_seconds() - before
    with open(stats) as f:
        result = json.load(f)
    result["cpu_seconds"] = cpu
    return result


def errors(image, reference, mask, out):
    """Image relMSE (and net of the reference's noise) and the masked indirect relMSE."""
    base = os.path.splitext(image)[0]
    beauty = compare(image, reference, base + ".beauty.json")
    glossy = compare(image, reference, base + ".glossy.json", "indirect",
                     ["--mask", mask, "--mask-aov", "sdrc-hits"])
    return {"relmse": beauty["relmse"], "relmse_net": beauty["relmse_net"],
            "glossy_indirect_relmse": glossy["relmse"], "glossy_pixels": glossy["pixels"]}


KEYS = ["relmse", "relmse_net", "glossy_indirect_relmse"]


def log_interpolate(t, a, b):
    """Errors at time t from points a, b (dicts with 'seconds' and KEYS), log-log."""
    if a["seconds"] == b["seconds"]:
        return {k: a[k] for k in KEYS}
    f = (math.log(t) - math.log(a["seconds"])) / (math.log(b["seconds"]) - math.log(a["seconds"]))
    result = {}
    for k in KEYS:
        if a[k] is None or b[k] is None or a[k] <= 0 or b[k] <= 0:
            result[k] = None
        else:
            result[k] = math.exp(math.log(a[k]) + f * (math.log(b[k]) - math.log(a[k])))
    return result


CLOCK = "cpu"


def seconds(stats):
    return stats["cpu_seconds"] if CLOCK == "cpu" else stats["seconds"]["render"]


def at_time(target, runs):
    """Errors of `runs` (sorted by time) at `target`: interpolated between the runs that bracket
    it, else the nearest run's scaled by its time over target (error ~ 1 / time). Returns the
    errors and whether they were interpolated."""
    below = [r for r in runs if r["seconds"] <= target]
    above = [r for r in runs if r["seconds"] >= target]
    if below and above:
        return log_interpolate(target, below[-1], above[0]), True
    nearest = below[-1] if below else above[0]
    scale = nearest["seconds"] / target
    return {k: (nearest[k] * scale if nearest[k] is not None else None) for k in KEYS}, False


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=os.path.join(ROOT, "scenes", "kettle"))
    parser.add_argument("--pt-spp", type=int, default=1024,
                        help="path tracer's samples per pixel (a power of two; its run must "
                             "outlast sdrc's)")
    parser.add_argument("--clock", choices=["cpu", "wall"], default="cpu")
    parser.add_argument("--sdrc-options", default="",
                        help="options of the sdrc render (quoted), e.g. \"--sdrc-interp 8\"")
    parser.add_argument("--rc-options", default="",
                        help="options of the rc renders (quoted), e.g. \"--ic-bounces 1\"")
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "glossy"))
    args, extra = parse_with_extra(parser, argv)
    global CLOCK
    CLOCK = args.clock
    sdrc_options = shlex.split(args.sdrc_options)
    rc_options = shlex.split(args.rc_options)
    scene_dir = args.scene if os.path.isdir(args.scene) else os.path.dirname(args.scene)
    scene = os.path.join(scene_dir, "scene.json")
    reference = references.reference_path(scene_dir)
    os.makedirs(args.out, exist_ok=True)
    out = lambda name: os.path.join(args.out, name)

    for method in ["sdrc", "rc", "pt"]:
        render(scene, out("warm-%s.exr" % method),
               ["--method", method, "--spp", "1", "--width", "32", "--height", "32"] + extra)

    sdrc_stats = render(scene, out("sdrc.exr"), ["--method", "sdrc"] + sdrc_options + extra)
    mask = out("sdrc.exr")
    target = seconds(sdrc_stats)
    spp = sdrc_stats["spp"]
    sdrc = dict(errors(out("sdrc.exr"), reference, mask, args.out), seconds=target, spp=spp)

    rc_runs = []
    rc_spp = spp
    for attempt in range(2):
        name = out("rc-%d.exr" % rc_spp)
        stats = render(scene, name, ["--method", "rc", "--spp", str(rc_spp)] + rc_options + extra)
        rc_runs.append(dict(errors(name, reference, mask, args.out), seconds=seconds(stats),
                            spp=rc_spp))
        next_spp = max(1, int(round(rc_spp * target / seconds(stats))))
        if next_spp == rc_spp:
            break
        rc_spp = next_spp
    rc_runs.sort(key=lambda r: r["seconds"])
    rc_at, rc_brackets = at_time(target, rc_runs)

    pt_stats = render(scene, out("pt.exr"),
                      ["--method", "pt", "--spp", str(args.pt_spp), "--save-every-pow2"] + extra)
    pt_total = seconds(pt_stats)  # a pass costs the same whatever its index
    pt_points = []
    n = 1
    while n <= args.pt_spp:
        name = out("pt.spp%d.exr" % n) if n < args.pt_spp else out("pt.exr")
        if os.path.isfile(name):
            pt_points.append(dict(errors(name, reference, mask, args.out),
                                  seconds=pt_total * n / args.pt_spp, spp=n))
        n *= 2
    if pt_points[-1]["seconds"] < target:
        sys.exit("glossy_equal_time: pt's %d spp (%.1f s) end before sdrc's %.1f s: raise "
                 "--pt-spp" % (args.pt_spp, pt_total, target))
    pt_at, _ = at_time(target, pt_points)

    result = {"scene": scene, "reference": reference, "clock": CLOCK, "seconds": target,
              "sdrc_options": sdrc_options, "rc_options": rc_options, "sdrc": sdrc,
              "rc_runs": rc_runs, "rc_at_sdrc_time": rc_at, "rc_bracketed": rc_brackets,
              "pt_points": pt_points, "pt_at_sdrc_time": pt_at, "extra_options": extra}
    with open(out("glossy_equal_time.json"), "w") as f:
        json.dump(result, f, indent=2)

    def ratio(a, b):
        return "%.2f×" % (a / b) if a and b else "–"

    print("At sdrc's time, %.1f s (%s clock; %s, %d spp %s; %d glossy pixels):"
          % (target, CLOCK, os.path.relpath(scene, ROOT), spp, " ".join(sdrc_options),
             sdrc["glossy_pixels"]))
    print("| method | image relMSE | net of the reference | glossy-pixel indirect relMSE |")
    print("| --- | ---: | ---: | ---: |")
    for name, e in [("sdrc", sdrc), ("rc" + ("" if rc_brackets else " (scaled, 1/time)"), rc_at),
                    ("pt", pt_at)]:
        print("| %s | %.3g | %s | %.3g |" % (
            name, e["relmse"], "%.3g" % e["relmse_net"] if e["relmse_net"] is not None else "–",
            e["glossy_indirect_relmse"]))
    print("rc / sdrc: image %s, glossy indirect %s; pt / sdrc: image %s, glossy indirect %s" % (
        ratio(rc_at["relmse"], sdrc["relmse"]),
        ratio(rc_at["glossy_indirect_relmse"], sdrc["glossy_indirect_relmse"]),
        ratio(pt_at["relmse"], sdrc["relmse"]),
        ratio(pt_at["glossy_indirect_relmse"], sdrc["glossy_indirect_relmse"])))
    for r in rc_runs:
        print("rc at %d spp: %.1f s, image %.3g, glossy indirect %.3g" % (
            r["spp"], r["seconds"], r["relmse"], r["glossy_indirect_relmse"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
