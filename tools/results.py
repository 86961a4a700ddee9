#!/usr/bin/env python3
"""Regenerates docs/results.md: error-against-time charts and tables of every method on every
shipped scene with a reference, the POV-Ray peer on the Cornell box, and `radcache bench all`.

Runs tools/sweep.py for each scene (outputs under OUT/SCENE, charts copied to
docs/results/SCENE-*.png), then `radcache bench all`, and writes docs/results.md with the machine,
device, date and git revision. About 20 minutes on 2 CPU cores with PoCL; run it on an otherwise
idle machine, since every figure is a time.

Usage: tools/results.py [--scenes cornell-box two-rooms] [--no-povray] [--out build/results]
           [-- extra radcache render options, e.g. --device 0:0]
"""

import argparse
import json
import os
import shutil
import subprocess
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")
DOCS = os.path.join(ROOT, "docs")
# Each scene's knobs: wide enough that the curves overlap in error.
PT_SPP = ["1", "2", "4", "8", "16", "32", "64", "128", "256", "512"]
IC_ACCURACY = ["0.6", "0.45", "0.35", "0.25"]
IC_SPP = ["4", "16"]
METHODS = ["pt", "ic", "ic-ivg", "ivg", "ivg-gather"]
IVG_PHOTONS = ["65536", "262144", "1048576"]
GATHER_RAYS = ["4", "16", "36"]  # per camera sample, at GATHER_SPP samples per pixel
GATHER_SPP = "4"


def run(command):
    print("+ " + " ".join(command), flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("results: %s failed:\n%s%s" % (" ".join(command), result.stdout,
                                                 result.stderr))
    return result.stdout


def number(value, digits=3):
    return "" if value in ("", None) else "%.*g" % (digits, value)


def scene_section(report, chart_names):
    lines = ["## %s" % report["scene"], ""]
    for chart in chart_names:
        lines += ["![%s](results/%s)" % (chart, chart), ""]
    lines += ["| curve | setting | render s | relMSE | FLIP | indirect relMSE | records |",
              "| --- | --- | ---: | ---: | ---: | ---: | ---: |"]
    for r in report["rows"]:
        lines.append("| %s | %s | %s | %s | %s | %s | %s |" % (
            r["curve"], r["setting"], number(r["render_seconds"]), number(r["relmse"]),
            number(r["flip"]), number(r["indirect_relmse"]), r["records"]))
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
            "run does not reach it; the references' own noise, roughly 1e-4, is in every "
            "error):", "",
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


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", nargs="+", default=["cornell-box", "two-rooms"])
    parser.add_argument("--no-povray", action="store_true", help="leave the POV-Ray peer out")
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "results"))
    if "--" in argv:
        split = argv.index("--")
        args = parser.parse_args(argv[:split])
        extra = argv[split + 1:]
    else:
        args = parser.parse_args(argv)
        extra = []
    os.makedirs(os.path.join(DOCS, "results"), exist_ok=True)
    os.makedirs(args.out, exist_ok=True)

    sections = []
    reports = []
    for scene in args.scenes:
        out = os.path.join(args.out, scene)
        command = [sys.executable, os.path.join(ROOT, "tools", "sweep.py"),
                   os.path.join("scenes", scene), "--out", out, "--methods"] + METHODS + [
                   "--pt-spp"] + PT_SPP + ["--ic-accuracy"] + IC_ACCURACY + ["--ic-spp"] + IC_SPP + [
                   "--ivg-photons"] + IVG_PHOTONS + ["--gather-rays"] + GATHER_RAYS + ["--gather-spp", GATHER_SPP]
        if scene == "cornell-box" and not args.no_povray and shutil.which("povray"):
            command.append("--povray")
        if extra:
            command += ["--"] + extra
        run(command)
        with open(os.path.join(out, "sweep.json")) as f:
            report = json.load(f)
        reports.append(report)
        charts = []
        for chart in report["charts"]:
            name = "%s-%s" % (scene, chart)
            shutil.copyfile(os.path.join(out, chart), os.path.join(DOCS, "results", name))
            charts.append(name)
        sections += scene_section(report, charts) + equal_error_lines(report)

    # bench all measures every device unless the renders were given one.
    bench_device = []
    if "--device" in extra:
        at = extra.index("--device")
        bench_device = extra[at:at + 2]
    table = run([RADCACHE, "bench", "all", "--json", os.path.join(args.out, "bench-all.json")] +
                bench_device)

    first = reports[0] if reports else {"date": "", "machine": "", "device": "", "git": ""}
    lines = [
        "# Results",
        "",
        "Error against time for every method on the shipped scenes that have a path-traced "
        "reference, and every kernel family's throughput. Generated by `tools/results.py%s` "
        "(this file and `docs/results/*.png`; the sweeps' images, CSV, JSON and HTML pages with "
        "equal-time crops and error images are left in `%s`)." % (
            (" " + " ".join(argv)) if argv else "", os.path.relpath(args.out, ROOT)),
        "",
        "- Date: %s; git %s." % (first["date"], first["git"]),
        "- Machine: %s." % first["machine"],
        "- Device: %s." % first["device"],
        "- Error: relMSE = mean over pixels and channels of (v − r)² / (r² + 0.01) against the "
        "scene's reference (`radcache compare`); FLIP = mean HDR-FLIP (flip-evaluator) of the "
        "image. 'indirect' is the indirect layer (light that bounced at least once).",
        "- Time: render phase of `radcache render --stats` (scene loading, device start-up and "
        "image writing excluded; kernel binaries warm, so compilation is excluded); POV-Ray: "
        "wall clock of its whole process (parsing included), all cores.",
        "- The references are path-traced at 4096 samples per pixel: their own noise puts a "
        "floor of roughly 1e-4 under every relMSE here.",
        "",
    ] + sections + [
        "## Kernel throughput (`radcache bench all`)",
        "",
        "```",
        table.rstrip(),
        "```",
        "",
    ]
    with open(os.path.join(DOCS, "results.md"), "w") as f:
        f.write("\n".join(lines))
    print("written docs/results.md and docs/results/*.png")


if __name__ == "__main__":
    main(sys.argv[1:])
