#!/usr/bin/env python3
"""Speed-versus-accuracy sweep of radcache's methods on one scene (DESIGN.md §7).

Runs every method over its quality knobs (spp for `pt`; accuracy, rays per record and camera
samples for `ic`), measures each image against the scene's reference (RMSE and relMSE through
`radcache compare`, HDR-FLIP through the flip-evaluator package) and writes

  OUT/sweep.csv, OUT/sweep.json   one row per run, the columns below
  OUT/error-vs-time.png           log-log relMSE of the image against render time, one curve per
                                  method, the Pareto front over all runs marked
  OUT/indirect-error-vs-time.png  the same for the indirect layer (methods that write it)
  OUT/index.html                  both charts, equal-time crops of every curve beside the
                                  reference's, and false-colour relMSE images

Methods and their knobs: pt (--pt-spp), ic (--ic-accuracy x --ic-rays x --ic-spp), ic-ivg (ic whose
records read the irradiance vector grid: --ic-accuracy at the first --ic-spp and --ic-rays), ivg
(--ivg-photons x --ivg-grid at --ivg-spp camera samples), ivg-gather (--gather-rays per camera
sample at --gather-spp camera samples, the grid at its defaults).

Columns: scene, method, curve, setting, spp, accuracy, ic_rays, photons, grid, gather_rays,
wall_seconds, render_seconds, kernel_seconds, compile_seconds, rmse, relmse, flip,
indirect_relmse, records, device, image, relmse_net.

relmse_net is the image's relMSE net of the reference's own noise (`radcache compare`: relmse
minus the mean of (stddev^2/spp_ref)/(r^2+0.01)); empty unless the reference has a stddev layer
and its sample count is known (`spp` of REF.stats.json or REF.json beside it, REF the reference's
name without .exr). It may be slightly negative for an image as good as the reference.

Times. render_seconds is the render phase of `radcache render --stats` (G-buffer to final
image; scene loading, device start-up and image writing excluded); it is the chart's time axis.
wall_seconds is the whole process; kernel_seconds the sum of the kernels' device times from
OpenCL profiling events. Kernel compilation is excluded: one untimed render per method at the
sweep's resolution and one sample per pixel first fills the kernel binary cache and lets the
device generate code for the launch shapes, and compile_seconds (the timed run's program builds,
from that cache) says what was left. Peers (POV-Ray, `--povray`) are timed by the wall clock of the
whole peer process, parsing included.

Usage: tools/sweep.py SCENE [--reference EXR] [--methods pt ic ...] [--pt-spp 1 2 4 ...]
           [--ic-accuracy ...] [--ic-rays ...] [--ic-spp ...] [--ivg-photons ...] [--ivg-grid ...]
           [--ivg-spp N] [--gather-rays ...] [--gather-spp N] [--width N --height N]
           [--povray [SETTING ...]] [--out DIR] [-- extra radcache render options]
SCENE is a scene directory or its scene.json; the reference defaults to reference.exr beside it.
The radcache executable is build/radcache, or $RADCACHE when set.
"""

import argparse
import csv
import datetime
import html
import json
import math
import os
import platform
import shutil
import subprocess
import sys
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")
COLUMNS = ["scene", "method", "curve", "setting", "spp", "accuracy", "ic_rays", "photons", "grid",
           "gather_rays", "wall_seconds", "render_seconds", "kernel_seconds", "compile_seconds",
           "rmse", "relmse", "flip", "indirect_relmse", "records", "device", "image", "relmse_net"]
METHODS = ["pt", "ic", "ic-ivg", "ivg", "ivg-gather"]
METHOD_COLOURS = {"pt": "tab:blue", "ic": "tab:orange", "ic-ivg": "tab:brown", "ivg": "tab:purple",
                  "ivg-gather": "tab:red", "povray": "tab:green"}


def fail(message):
    sys.exit("sweep: " + message)


def run_radcache(args):
    result = subprocess.run([RADCACHE] + args, capture_output=True, text=True)
    if result.returncode != 0:
        fail("radcache %s failed:\n%s%s" % (" ".join(args), result.stdout, result.stderr))
    return result.stdout


def compare(image, reference, aov, json_path, error_image=None):
    args = ["compare", image, reference, "--aov", aov, "--json", json_path]
    if error_image:
        args += ["--error-image", error_image]
    run_radcache(args)
    with open(json_path) as f:
        return json.load(f)


def has_layer(image, layer):
    result = subprocess.run([RADCACHE, "compare", image, image, "--aov", layer],
                            capture_output=True, text=True)
    return result.returncode == 0


def flip_error(image, reference):
    """Mean HDR-FLIP of the beauty channels (flip-evaluator reads R, G, B of an EXR)."""
    import flip_evaluator
    _, mean, _ = flip_evaluator.evaluate(reference, image, "HDR", applyMagma=False)
    return float(mean)


def scene_paths(scene, reference):
    scene_json = os.path.join(scene, "scene.json") if os.path.isdir(scene) else scene
    if not os.path.isfile(scene_json):
        fail("scene not found: %s" % scene_json)
    reference = reference or os.path.join(os.path.dirname(scene_json), "reference.exr")
    if not os.path.isfile(reference):
        fail("reference not found: %s (pass --reference)" % reference)
    return os.path.abspath(scene_json), os.path.abspath(reference)


def render(scene, image, options):
    """One timed `radcache render`; returns the wall seconds and the --stats JSON."""
    stats_path = os.path.splitext(image)[0] + ".stats.json"
    start = time.perf_counter()
    run_radcache(["render", scene, "-o", image, "--stats", stats_path, "--quiet"] + options)
    wall = time.perf_counter() - start
    with open(stats_path) as f:
        return wall, json.load(f)


def radcache_runs(args):
    """(method, curve, setting, knobs, options) for every radcache run of the sweep."""
    runs = []
    if "pt" in args.methods:
        for spp in args.pt_spp:
            runs.append(("pt", "pt", "spp=%d" % spp, {"spp": spp},
                         ["--method", "pt", "--spp", str(spp)]))
    if "ic" in args.methods:
        for rays in args.ic_rays:
            for spp in args.ic_spp:
                curve = "ic %d rays, %d spp" % (rays, spp)
                for accuracy in args.ic_accuracy:
                    runs.append(("ic", curve, "accuracy=%g rays=%d spp=%d" % (accuracy, rays, spp),
                                 {"spp": spp, "accuracy": accuracy, "ic_rays": rays},
                                 ["--method", "ic", "--spp", str(spp), "--accuracy", str(accuracy),
                                  "--ic-rays", str(rays)]))
    if "ic-ivg" in args.methods:
        rays, spp = args.ic_rays[0], args.ic_spp[0]
        for accuracy in args.ic_accuracy:
            runs.append(("ic-ivg", "ic + grid, %d spp" % spp,
                         "accuracy=%g rays=%d spp=%d" % (accuracy, rays, spp),
                         {"spp": spp, "accuracy": accuracy, "ic_rays": rays, "grid": "auto"},
                         ["--method", "ic", "--ic-ivg", "--spp", str(spp), "--accuracy",
                          str(accuracy), "--ic-rays", str(rays)]))
    if "ivg" in args.methods:
        for grid in args.ivg_grid:
            curve = "ivg, grid %s, %d spp" % (grid, args.ivg_spp)
            for photons in args.ivg_photons:
                runs.append(("ivg", curve, "photons=%d grid=%s" % (photons, grid),
                             {"spp": args.ivg_spp, "photons": photons, "grid": grid},
                             ["--method", "ivg", "--spp", str(args.ivg_spp), "--photons",
                              str(photons), "--grid", grid]))
    if "ivg-gather" in args.methods:
        spp = args.gather_spp
        for gathers in args.gather_rays:
            runs.append(("ivg-gather", "ivg-gather, %d spp" % spp,
                         "gather_rays=%d spp=%d" % (gathers, spp),
                         {"spp": spp, "gather_rays": gathers, "grid": "auto"},
                         ["--method", "ivg-gather", "--spp", str(spp), "--gather-rays",
                          str(gathers)]))
    return runs


def measure(row, image, reference, out, name):
    """Fills the error columns of a row; writes OUT/NAME.error.png."""
    error_png = os.path.join(out, name + ".error.png")
    beauty = compare(image, reference, "beauty", os.path.join(out, name + ".compare.json"),
                     error_png)
    row["rmse"] = beauty["rmse"]
    row["relmse"] = beauty["relmse"]
    # Net of the reference's noise: null in compare's JSON when it is not known.
    net = beauty.get("relmse_net")
    row["relmse_net"] = "" if net is None else net
    row["flip"] = flip_error(image, reference)
    row["indirect_relmse"] = ""
    if has_layer(image, "indirect") and has_layer(reference, "indirect"):
        indirect = compare(image, reference, "indirect",
                           os.path.join(out, name + ".indirect.json"))
        row["indirect_relmse"] = indirect["relmse"]
    row["image"] = os.path.relpath(image, out)


def povray_rows(args, scene, reference, out):
    """Runs the POV-Ray peer (tools/peers/povray) and returns its rows."""
    if os.path.basename(os.path.dirname(scene)) != "cornell-box":
        fail("--povray: the POV-Ray peer exists for scenes/cornell-box only")
    peer_out = os.path.join(out, "povray")
    command = [os.path.join(ROOT, "tools", "peers", "povray", "run.sh"), peer_out] + args.povray
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        fail("POV-Ray peer failed:\n%s%s" % (result.stdout, result.stderr))
    rows = []
    with open(os.path.join(peer_out, "povray.csv")) as f:
        for peer in csv.DictReader(f):
            name = "povray-" + peer["setting"]
            image = os.path.join(out, name + ".exr")
            shutil.copyfile(os.path.join(peer_out, peer["setting"] + ".exr"), image)
            row = {"method": "povray", "curve": "POV-Ray 3.7 radiosity",
                   "setting": peer["setting"], "spp": "", "accuracy": "", "ic_rays": "",
                   "photons": "", "grid": "", "gather_rays": "",
                   "wall_seconds": float(peer["seconds"]),
                   "render_seconds": float(peer["seconds"]), "kernel_seconds": "",
                   "compile_seconds": "", "records": "",
                   "device": "POV-Ray, %s threads" % peer["threads"]}
            measure(row, image, reference, out, name)
            rows.append(row)
    return rows


def pareto_front(points):
    """The points (time, error) not beaten in both time and error by another, by time."""
    front = []
    for t, e in sorted(points):
        if not front or e < front[-1][1]:
            front.append((t, e))
    return front


def draw_chart(rows, key, title, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    points = [r for r in rows if r.get(key) not in ("", None) and r[key] > 0]
    if not points:
        return False
    figure, axes = plt.subplots(figsize=(7, 5), dpi=110)
    curves = []
    for r in points:
        if r["curve"] not in curves:
            curves.append(r["curve"])
    markers = "osD^v<>p*h"
    styles = ["-", ":", "-.", (0, (5, 1))]
    seen = {}
    for i, curve in enumerate(curves):
        members = sorted((r for r in points if r["curve"] == curve),
                         key=lambda r: r["render_seconds"])
        method = members[0]["method"]
        # Curves of one method share its colour and differ by line style.
        style = styles[seen.get(method, 0) % len(styles)]
        seen[method] = seen.get(method, 0) + 1
        axes.plot([r["render_seconds"] for r in members], [r[key] for r in members],
                  marker=markers[i % len(markers)], color=METHOD_COLOURS.get(method),
                  linestyle=style, label=curve)
    front = pareto_front([(r["render_seconds"], r[key]) for r in points])
    axes.plot([t for t, _ in front], [e for _, e in front], color="black", linestyle="--",
              linewidth=1, zorder=0, label="Pareto front")
    axes.scatter([t for t, _ in front], [e for _, e in front], s=120, facecolors="none",
                 edgecolors="black", linewidths=1, zorder=3)
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("render time (s)")
    axes.set_ylabel("relMSE")
    axes.set_title(title)
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)
    return True


def tonemapped(path):
    import flip_evaluator
    import numpy
    image = numpy.clip(flip_evaluator.load(path), 0.0, 1.0)
    return numpy.where(image <= 0.0031308, 12.92 * image,
                       1.055 * numpy.power(image, 1.0 / 2.4) - 0.055)


def crop_box(width, height, crop):
    if crop:
        x, y, w, h = crop
    else:  # the middle half of the image
        x, y, w, h = width // 4, height // 4, max(1, width // 2), max(1, height // 2)
    return x, y, min(w, width - x), min(h, height - y)


def save_crop(source, path, box):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    x, y, w, h = box
    plt.imsave(path, source[y:y + h, x:x + w])


def equal_time_rows(rows):
    """One row per curve: the run whose time is nearest (log scale) to the median time."""
    times = sorted(r["render_seconds"] for r in rows)
    target = times[len(times) // 2]
    chosen = {}
    for r in rows:
        distance = abs(math.log(r["render_seconds"] / target))
        if r["curve"] not in chosen or distance < chosen[r["curve"]][0]:
            chosen[r["curve"]] = (distance, r)
    return target, [r for _, r in chosen.values()]


def write_html(report, out, crop):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = report["rows"]
    reference = tonemapped(report["reference"])
    height, width = reference.shape[:2]
    box = crop_box(width, height, crop)
    save_crop(reference, os.path.join(out, "reference.crop.png"), box)
    target, chosen = equal_time_rows(rows)
    cells = []
    for r in chosen:
        name = os.path.splitext(r["image"])[0]
        save_crop(tonemapped(os.path.join(out, r["image"])), os.path.join(out, name + ".crop.png"),
                  box)
        save_crop(plt.imread(os.path.join(out, name + ".error.png"))[..., :3],
                  os.path.join(out, name + ".error.crop.png"), box)
        cells.append(
            "<td><b>%s</b><br>%s<br>%.3g s, relMSE %.3g, FLIP %.3g<br>"
            "<img src='%s'><br><img src='%s'></td>" %
            (html.escape(r["curve"]), html.escape(r["setting"]), r["render_seconds"], r["relmse"],
             r["flip"], html.escape(name + ".crop.png"), html.escape(name + ".error.crop.png")))
    charts = "".join("<img src='%s'>" % c for c in report["charts"])
    table = "".join(
        "<tr>%s</tr>" % "".join("<td>%s</td>" % html.escape(
            ("%.4g" % r[c]) if isinstance(r[c], float) else str(r[c])) for c in COLUMNS)
        for r in rows)
    page = """<!doctype html><meta charset="utf-8"><title>radcache sweep: {scene}</title>
<style>body{{font-family:sans-serif}} td{{vertical-align:top;padding:4px}}
img{{image-rendering:pixelated;max-width:100%}}</style>
<h1>{scene}</h1><p>{when}, {device}, git {git}. Time axis: {timing}</p>
<p>Command: <code>{command}</code></p>{charts}
<h2>Equal time (about {target:.3g} s)</h2>
<p>Crop x={x} y={y} {w}x{h} of each curve's run nearest in time; below each, its relMSE per pixel
(log10 from -5, black, to 0, white).</p>
<table><tr><td><b>reference</b><br><img src="reference.crop.png"></td>{cells}</tr></table>
<h2>All runs</h2><table border=1 cellspacing=0><tr>{header}</tr>{table}</table>
""".format(scene=html.escape(report["scene"]), when=report["date"],
           device=html.escape(report["device"]), git=report["git"],
           timing=html.escape(report["timing"]), command=html.escape(report["command"]),
           charts=charts, target=target, x=box[0], y=box[1], w=box[2], h=box[3],
           cells="".join(cells), header="".join("<th>%s</th>" % c for c in COLUMNS), table=table)
    with open(os.path.join(out, "index.html"), "w") as f:
        f.write(page)


def git_revision():
    result = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True)
    return result.stdout.strip() or "unknown"


def machine():
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return "%s, %d cores" % (model, os.cpu_count() or 0)


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n")[0],
        epilog="Everything after -- goes to every radcache render (e.g. -- --device 0:0).")
    parser.add_argument("scene", help="scene directory or scene.json")
    parser.add_argument("--reference", help="reference image (default: reference.exr beside it)")
    parser.add_argument("--methods", nargs="+", default=["pt", "ic"], choices=METHODS)
    parser.add_argument("--pt-spp", nargs="+", type=int, default=[1, 2, 4, 8, 16, 32, 64, 128])
    parser.add_argument("--ic-accuracy", nargs="+", type=float, default=[0.6, 0.45, 0.35, 0.25])
    parser.add_argument("--ic-rays", nargs="+", type=int, default=[1024])
    parser.add_argument("--ic-spp", nargs="+", type=int, default=[4, 16])
    parser.add_argument("--ivg-photons", nargs="+", type=int, default=[65536, 262144, 1048576])
    parser.add_argument("--ivg-grid", nargs="+", default=["auto"],
                        help="grid resolutions (NxMxK or auto)")
    parser.add_argument("--ivg-spp", type=int, default=4)
    parser.add_argument("--gather-rays", nargs="+", type=int, default=[16, 64, 144])
    parser.add_argument("--gather-spp", type=int, default=1,
                        help="camera samples per pixel of ivg-gather")
    parser.add_argument("--width", type=int, help="override the scene's resolution")
    parser.add_argument("--height", type=int)
    parser.add_argument("--povray", nargs="*", metavar="SETTING",
                        help="add the POV-Ray peer (Cornell box only): its settings, default all")
    parser.add_argument("--crop", type=int, nargs=4, metavar=("X", "Y", "W", "H"),
                        help="equal-time crop (default: the middle half)")
    parser.add_argument("--out", help="output directory (default build/sweep/SCENE)")
    if "--" in argv:
        split = argv.index("--")
        args = parser.parse_args(argv[:split])
        args.extra = argv[split + 1:]
    else:
        args = parser.parse_args(argv)
        args.extra = []
    for name in ("pt_spp", "ic_rays", "ic_spp", "ivg_photons", "gather_rays"):
        if any(v < 1 for v in getattr(args, name)):
            parser.error("--%s: values must be positive" % name.replace("_", "-"))
    if any(not 0.0 < a for a in args.ic_accuracy):
        parser.error("--ic-accuracy: values must be positive")
    return args


def main(argv):
    args = parse_arguments(argv)
    if not os.access(RADCACHE, os.X_OK):
        fail("build radcache first (see README): %s is missing" % RADCACHE)
    try:
        import flip_evaluator  # noqa: F401
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as e:
        fail("%s: install the tools' Python packages: python3 -m pip install -r "
             "tools/requirements.txt" % e)
    scene, reference = scene_paths(args.scene, args.reference)
    scene_name = os.path.basename(os.path.dirname(scene))
    out = os.path.abspath(args.out or os.path.join(ROOT, "build", "sweep", scene_name))
    os.makedirs(out, exist_ok=True)
    size = []
    if args.width:
        size += ["--width", str(args.width)]
    if args.height:
        size += ["--height", str(args.height)]

    runs = radcache_runs(args)
    # Warm up, untimed: one render per method at the sweep's resolution and one sample per
    # pixel fills the kernel binary cache and lets the device generate code for the launch
    # shapes the timed runs use (PoCL does that on a shape's first launch).
    for method in sorted({method for method, *_ in runs}):
        options = ["--method", "ic", "--ic-ivg"] if method == "ic-ivg" else ["--method", method]
        if method in ("ivg", "ivg-gather", "ic-ivg"):
            options += ["--photons", "1000"]
        render(scene, os.path.join(out, "warm-%s.exr" % method),
               options + ["--spp", "1"] + size + args.extra)
    rows = []
    device = ""
    for index, (method, curve, setting, knobs, options) in enumerate(runs):
        name = "%s-%02d" % (method, index)
        image = os.path.join(out, name + ".exr")
        print("[%d/%d] %s %s" % (index + 1, len(runs), method, setting), flush=True)
        wall, stats = render(scene, image, options + size + args.extra)
        device = stats["device"]
        frame = stats["frames"][0] if stats.get("frames") else {}
        row = {"method": method, "curve": curve, "setting": setting,
               "spp": knobs.get("spp", ""), "accuracy": knobs.get("accuracy", ""),
               "ic_rays": knobs.get("ic_rays", ""), "grid": knobs.get("grid", ""),
               "photons": frame.get("grid", {}).get("photons", ""),
               "gather_rays": knobs.get("gather_rays", ""), "wall_seconds": wall,
               "render_seconds": stats["seconds"]["render"],
               "kernel_seconds": sum(k["seconds"] for k in stats["kernels"].values()),
               "compile_seconds": sum(b["seconds"] for b in stats.get("program_builds", [])),
               "records": frame.get("records", ""), "device": device}
        measure(row, image, reference, out, name)
        rows.append(row)
    if args.povray is not None:
        rows += povray_rows(args, scene, reference, out)
    for row in rows:
        row["scene"] = scene_name

    report = {
        "scene": scene_name, "reference": reference, "device": device, "machine": machine(),
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "git": git_revision(),
        "command": " ".join(["tools/sweep.py"] + argv),
        "timing": "render phase of radcache --stats (scene loading, device start-up and image "
                  "writing excluded; kernel binaries warm, compilation excluded); POV-Ray: wall "
                  "clock of the whole process",
        "columns": COLUMNS, "rows": rows, "charts": []}
    if draw_chart(rows, "relmse", "%s: image relMSE against time" % scene_name,
                  os.path.join(out, "error-vs-time.png")):
        report["charts"].append("error-vs-time.png")
    indirect = [dict(r, relmse_indirect=r["indirect_relmse"]) for r in rows]
    if draw_chart(indirect, "relmse_indirect", "%s: indirect relMSE against time" % scene_name,
                  os.path.join(out, "indirect-error-vs-time.png")):
        report["charts"].append("indirect-error-vs-time.png")
    with open(os.path.join(out, "sweep.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        for row in rows:
            writer.writerow({c: row[c] for c in COLUMNS})
    with open(os.path.join(out, "sweep.json"), "w") as f:
        json.dump(report, f, indent=2)
    write_html(report, out, args.crop)
    print("%-26s %-28s %9s %11s %8s" % ("curve", "setting", "seconds", "relMSE", "FLIP"))
    for r in rows:
        print("%-26s %-28s %9.3f %11.4g %8.4f" % (r["curve"], r["setting"], r["render_seconds"],
                                                  r["relmse"], r["flip"]))
    print("written to %s (sweep.csv, sweep.json, index.html)" % out)


if __name__ == "__main__":
    main(sys.argv[1:])
