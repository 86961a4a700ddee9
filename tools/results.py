#!/usr/bin/env python3
"""Regenerates docs/results.md: error-against-time charts and tables of every method on every
shipped scene with a reference, the POV-Ray peer on the Cornell box, and `radcache bench all`.

Runs tools/sweep.py for each scene with every method (--methods all: each method of radcache's
registry that has quality knobs, and ic-ivg) at the sweep's default knobs and repeats (outputs
under OUT/SCENE, charts copied to docs/results/SCENE-*.png), then `radcache bench all`, and writes
docs/results.md with the machine, device, date and git revision. Each sweep renders every point
--repeats times (default 3): the tables give the median render time and the fastest and slowest
repeat. Every figure is a time: run it on an otherwise idle machine. Estimated from timed single
points (not a timed full run): 35-40 minutes per 512-pixel scene on 2 CPU cores with PoCL, less
for the 256-pixel moving sphere (docs/benchmarks.md, "Error against time").

Usage: tools/results.py [--scenes cornell-box two-rooms ...] [--repeats N] [--no-povray]
           [--no-peers] [--no-bench] [--note TEXT] [--quick|--tiny] [--reuse]
           [--out build/results] [-- extra radcache render options, e.g. --device 0:0]
Every sweep has the peers (tools/sweep.py --denoise --mitsuba: each method's images through
OIDN, and Mitsuba 3's path tracer; each skipped with a warning without its package or, for
Mitsuba, on a scene its exporter refuses) unless --no-peers, and the page opens with which curve
wins at 10 s, 100 s and 1000 s on each scene (tools/winners.py).
--tiny sweeps a few points per scene (TINY below: pt to 64 spp, one point of each caching method,
Mitsuba to 16 spp): 17 minutes for the 512-pixel Cornell box on 2 cores shared with other
builds (docs/lab/peers.md), for a machine that cannot spend hours.
--quick sweeps fewer points per scene (QUICK below: pt to 256 spp, ic and rc at 1024 rays and
the default spacing, the grid at its automatic size, two decomposition clusters; every accuracy
and photon count kept), about a third of the time. --reuse takes a scene's sweep from OUT/SCENE/
sweep.json where one is there instead of sweeping it again (each scene's section quotes the
sweep command that made it), and `bench all`'s table from OUT/bench-all.txt.
The default scenes are every shipped scene with a reference (scenes/README.md); an animated
scene is swept at its first frame.
"""

import argparse

from winners import winners_lines, winners_section
import json
import os
import shlex
import shutil
import sys

from radcache_tools import ROOT, radcache
from radcache_tools.arguments import parse_with_extra

DOCS = os.path.join(ROOT, "docs")
# tools/sweep.py's knobs under --quick.
QUICK = ["--pt-spp", "1", "2", "4", "8", "16", "32", "64", "128", "256", "--ic-rays", "1024",
         "--ic-min-spacing", "default", "--rc-rays", "1024", "--ivg-grid", "auto",
         "--decomp-cluster", "20%", "5%"]
# tools/sweep.py's knobs under --tiny: a few pt points and one point of each caching method.
TINY = ["--pt-spp", "1", "4", "16", "64", "--ic-accuracy", "0.6", "--ic-rays", "1024",
        "--ic-min-spacing", "default", "--rc-rays", "1024", "--sdrc-interp", "1", "--ivg-grid",
        "auto", "--ivg-photons", "262144", "--gather-rays", "4", "--decomp-cluster", "20%"]
# The Mitsuba peer's samples per pixel: the sweep's default, and under --tiny.
TINY_MITSUBA = ["4", "16"]


def run(command):
    """COMMAND (a list) echoed; its stdout; exits naming it when it fails."""
    return radcache.run_command(command, "results", echo=True)


def out_folder(out):
    """The sweeps' folder as the page names it: relative to the repository when inside it."""
    out = os.path.abspath(out)
    inside = os.path.commonpath([out, ROOT]) == ROOT
    return os.path.relpath(out, ROOT) if inside else out


def number(value, digits=3):
    return "" if value in ("", None) else "%.*g" % (digits, value)


def spread(row):
    """The fastest and slowest repeat's render time, "" for a single run."""
    if row.get("repeats", 1) in ("", 1) or row.get("render_seconds_min") in ("", None):
        return ""
    return "%s–%s" % (number(row["render_seconds_min"]), number(row["render_seconds_max"]))


def reference_line(report):
    """Where the scene's reference came from and its own noise (relmse - relmse_net)."""
    reference = report["reference"]
    record_path = os.path.splitext(reference)[0] + ".json"
    text = "Reference: `%s`" % os.path.relpath(reference, ROOT)
    if os.path.isfile(record_path):
        with open(record_path) as f:
            record = json.load(f)
        text += " (%d samples per pixel, %s, git %s)" % (record["spp"], record["device"],
                                                       record["git"])
    noise = [r["relmse"] - r["relmse_net"] for r in report["rows"]
             if r.get("relmse_net") not in ("", None)]
    if noise:
        text += "; its own noise adds %s to every relMSE (subtracted in the net column)" % (
            number(noise[0], 2))
    return text + "."


def scene_section(report, chart_names):
    title = report["scene"]
    if report.get("frame"):
        title += ", frame %d" % report["frame"]
    lines = ["## %s" % title, "", reference_line(report), ""]
    for chart in chart_names:
        lines += ["![%s](results/%s)" % (chart, chart), ""]
    lines += ["| curve | setting | render s | fastest–slowest s | relMSE | net relMSE | FLIP | "
              "indirect relMSE | records |",
              "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for r in report["rows"]:
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["curve"], r["setting"], number(r["render_seconds"]), spread(r),
            number(r["relmse"]), number(r.get("relmse_net")), number(r["flip"]),
            number(r["indirect_relmse"]), r["records"]))
    lines += ["", "Sweep: `%s` (%s; %s)." % (report["command"], report["date"], report["timing"]),
              ""]
    return lines


def equal_error_lines(report):
    """For each run of another method: the path tracer's time to the same image and indirect
    relMSE, read off its curve (log-log interpolation), as a speed-up."""
    pt = sorted((r for r in report["rows"] if r["method"] == "pt"),
                key=lambda r: r["render_seconds"])
    lines = []
    for r in report["rows"]:
        if r["method"] == "pt":
            continue
        cells = []
        for key in ("relmse", "indirect_relmse"):
            if r[key] in ("", None):
                cells.append("")
                continue
            seconds = time_to_error(pt, key, r[key])
            cells.append("> %.1f×" % (pt[-1]["render_seconds"] / r["render_seconds"])
                         if seconds is None else "%.1f×" % (seconds / r["render_seconds"]))
        lines.append("| %s | %s | %s | %s | %s |" % (
            r["method"], r["setting"], number(r["render_seconds"]), cells[0], cells[1]))
    if not lines:
        return []
    return ["Equal-error speed-up over `pt` (the path tracer's time to the same relMSE on its "
            "curve above, log-log interpolated, over the method's time; `>` where `pt`'s longest "
            "run does not reach it; times are medians of the repeats; the reference's own "
            "noise, given above, is in every error):", "",
            "| method | setting | s | image | indirect |", "| --- | --- | ---: | ---: | ---: |"
            ] + lines + [""]


def time_to_error(curve, key, target):
    import math
    points = [(r["render_seconds"], r[key]) for r in curve if r[key] not in ("", None)]
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if e0 >= target >= e1 and e0 > e1:
            f = (math.log(e0) - math.log(target)) / (math.log(e0) - math.log(e1))
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0)))
    if points and target >= points[0][1]:
        return points[0][0]
    return None


def bench_section(table):
    """`bench all`'s table, or a line saying it was not run (--no-bench)."""
    lines = ["## Kernel throughput (`radcache bench all`)", ""]
    if table is None:
        return lines + ["Not measured in this run (`--no-bench`); the kernels' throughput is "
                        "measured in [`benchmarks.md`](benchmarks.md).", ""]
    return lines + ["```", table.rstrip(), "```", ""]


def scenes_phrase(scenes):
    """What the page covers: every shipped scene with a reference, or the ones named."""
    if sorted(scenes) == scenes_with_references():
        return "the shipped scenes that have a path-traced reference"
    return "%s (of the shipped scenes with a reference: %s; the others were not swept in this " \
           "run)" % (", ".join("`%s`" % s for s in scenes),
                     ", ".join("`%s`" % s for s in scenes_with_references()))


def preset(args):
    """tools/sweep.py's knobs and peers for the chosen preset."""
    knobs = TINY if args.tiny else QUICK if args.quick else []
    if args.no_peers:
        return knobs
    return knobs + ["--denoise", "--mitsuba"] + (TINY_MITSUBA if args.tiny else [])


def skipped_lines(report):
    """The curves a sweep skipped (a peer that refused the scene, a missing package)."""
    if not report.get("skipped"):
        return []
    return ["Not in this sweep: %s." % "; ".join(report["skipped"]), ""]


def scenes_with_references():
    """Every shipped scene with a reference (reference.exr, or reference/ of an animated one)."""
    folder = os.path.join(ROOT, "scenes")
    return sorted(name for name in os.listdir(folder)
                  if os.path.isfile(os.path.join(folder, name, "reference.exr")) or
                  os.path.isdir(os.path.join(folder, name, "reference")))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", nargs="+", default=scenes_with_references())
    parser.add_argument("--repeats", type=int, default=3,
                        help="timed renders of every point (tools/sweep.py --repeats)")
    parser.add_argument("--no-povray", action="store_true", help="leave the POV-Ray peer out")
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "results"))
    parser.add_argument("--quick", action="store_true", help="fewer points per sweep (QUICK)")
    parser.add_argument("--tiny", action="store_true",
                        help="a few points per sweep (TINY): pt, one point of each caching "
                             "method, Mitsuba at %s spp" % " ".join(TINY_MITSUBA))
    parser.add_argument("--no-bench", action="store_true",
                        help="leave `radcache bench all` out (the page then says so)")
    parser.add_argument("--note", help="one more line for the page's header (e.g. how loaded "
                                       "the machine was)")
    parser.add_argument("--no-peers", action="store_true",
                        help="leave out the Mitsuba peer and the +oidn curves")
    parser.add_argument("--reuse", action="store_true",
                        help="take a scene's existing OUT/SCENE/sweep.json instead of sweeping")
    args, extra = parse_with_extra(parser, argv)
    os.makedirs(os.path.join(DOCS, "results"), exist_ok=True)
    os.makedirs(args.out, exist_ok=True)

    sections = []
    reports = []
    winners = []
    for scene in args.scenes:
        out = os.path.join(args.out, scene)
        command = [sys.executable, os.path.join(ROOT, "tools", "sweep.py"),
                   os.path.join("scenes", scene), "--out", out, "--repeats", str(args.repeats),
                   "--methods", "all"] + preset(args)
        if scene == "cornell-box" and not args.no_povray and shutil.which("povray"):
            command.append("--povray")
        if extra:
            command += ["--"] + extra
        if not (args.reuse and os.path.isfile(os.path.join(out, "sweep.json"))):
            run(command)
        with open(os.path.join(out, "sweep.json")) as f:
            report = json.load(f)
        reports.append(report)
        charts = []
        for chart in report["charts"]:
            name = "%s-%s" % (scene, chart)
            shutil.copyfile(os.path.join(out, chart), os.path.join(DOCS, "results", name))
            charts.append(name)
        sections += (scene_section(report, charts) + skipped_lines(report) +
                     equal_error_lines(report))
        winners.append(winners_lines(report))

    # bench all measures every device unless the renders were given one.
    bench_device = []
    if "--device" in extra:
        at = extra.index("--device")
        bench_device = extra[at:at + 2]
    bench_text = os.path.join(args.out, "bench-all.txt")
    if args.no_bench:
        table = None
    elif args.reuse and os.path.isfile(bench_text):
        with open(bench_text) as f:
            table = f.read()
    else:
        table = radcache.run(["bench", "all", "--json", os.path.join(args.out, "bench-all.json")]
                             + bench_device, "results", echo=True)
        with open(bench_text, "w") as f:
            f.write(table)

    first = reports[0] if reports else {"date": "", "machine": "", "device": "", "git": ""}
    lines = [
        "# Results",
        "",
        "Error against time for every method on %s, and every kernel family's throughput. "
        "Generated by `tools/results.py%s` (this file and `docs/results/*.png`; the sweeps' "
        "images, CSV, JSON and HTML pages with equal-time crops and error images are left in "
        "`%s`)." % (scenes_phrase(args.scenes), (" " + shlex.join(argv)) if argv else "",
                    out_folder(args.out)),
        "",
        "- Date: %s; git %s." % (first["date"], first["git"]),
        "- Machine: %s." % first["machine"],
        "- Device: %s." % first["device"],
        "- Error: relMSE = mean over pixels and channels of (v − r)² / (r² + 0.01) against the "
        "scene's reference (`radcache compare`); FLIP = mean HDR-FLIP (flip-evaluator) of the "
        "image. 'indirect' is the indirect layer (light that bounced at least once).",
        "- Net relMSE: relMSE minus the reference's own noise (`radcache compare`'s "
        "relmse_net: the mean of (stddev²/spp_ref)/(r² + 0.01)); it may dip slightly below 0.",
        "- Time: render phase of `radcache render --stats` (scene loading, device start-up and "
        "image writing excluded; kernel binaries warm, so compilation is excluded), the median "
        "of %d repeats (the charts' bars and the tables' fastest–slowest span them; the "
        "repeats' images are checked bitwise identical); POV-Ray: wall clock of its whole "
        "process (parsing included), all cores, one run; Mitsuba 3 (its path tracer, "
        "[`peers.md`](peers.md)): `mi.render` alone, one run; `+oidn`: the point's time plus "
        "the denoise step's (OIDN with the albedo and normal layers, `tools/denoise.py`)." %
        args.repeats,
    ] + (["- Note: %s" % args.note] if args.note else []) + [
        "- References: path-traced by radcache ([`scenes/README.md`](../scenes/README.md)); each "
        "scene's section names its reference, samples per pixel, device and git revision; "
        "checked independently against Mitsuba 3's path tracer on the Cornell box and two-rooms "
        "(per-channel means: `tools/peers/mitsuba/check_reference.py`, the figures in "
        "[`lab/peers.md`](lab/peers.md)).",
        "",
    ] + winners_section(winners) + sections + bench_section(table)
    with open(os.path.join(DOCS, "results.md"), "w") as f:
        f.write("\n".join(lines))
    print("written docs/results.md and docs/results/*.png")


if __name__ == "__main__":
    main(sys.argv[1:])
