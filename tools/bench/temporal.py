#!/usr/bin/env python3
"""Temporal caching against per-frame caching over a clip (its targets: the speed-up at
equal per-frame relMSE, and the temporal error, flicker, at equal time), for irradiance caching
(`--method ic`, the default) or radiance caching (`--method rc`: the ladder is of radiance records'
rays, --rc-rays; --options sets the irradiance records').

On an animated scene with per-frame references (default scenes/moving-sphere), all in this one
invocation on one device with warm kernel binaries (one untimed small render first):

  1. `ic --temporal` over --frames: its time T and, against the references (`radcache compare
     --frames`, the references box-filtered to the render's resolution), the mean per-frame relMSE
     and the mean temporal error of the indirect layer (the caches' part of the image; the direct
     light is the same estimator in both) and of the beauty layer.
  2. Per-frame `ic` over the same frames at each --ladder hemisphere ray count (the first is the
     temporal render's own): its times and errors.
  3. Speed-up at equal error: the per-frame time at the temporal render's indirect relMSE,
     interpolated log-log between the ladder runs that bracket it, over T. When every ladder run
     is more accurate, the cheapest one's time over T is a lower bound ("≥"); when every one is
     less accurate, the most accurate one's time over T is an upper bound ("≤").
  4. Flicker at equal time: per-frame caching's mean temporal error at T, interpolated log-log
     in time between the ladder runs (or the nearest run's, said so), over the temporal render's.
  5. A chart of per-frame relMSE and temporal error over the clip (tools/flicker_chart.py,
     needs matplotlib): --chart FILE.

--slow K renders the temporal run on the same animation K times slower: a copy of the scene
(OUT/slow/scene.json, its files' paths made absolute) whose keyframes and clip range have their
frame numbers multiplied by K, rendered over frames K·A..K·B; its frame K·j has frame j's pose
exactly (keyframes interpolate linearly in the frame number), so its every K-th frame is compared
with reference j. Per-frame caching renders every frame on its own, so its time for the slow clip
is its time for the referenced frames A..B times (K(B − A) + 1) / (B − A + 1) (the frames in
between taken at the referenced frames' mean cost); its errors are those of the referenced
frames. The temporal error (flicker) is then between frames K apart: neither reported nor
charted. Slow motion sampled densely is how the report's clips move (7.6× on a 400-frame "Cube
in a Box", Gautron et al. 2006 §6).

References every K-th frame only (scenes/walkthrough: 0, 4, ..., 44): the renders' frames A,
A + K, ... (K found from the reference folder) are compared with them (OUT/kth/), and the temporal
error is then between frames K apart, not flicker: reported as such.

Per clip it also reports the temporal run's first-level records computed per frame (created and
recomputed, frame 0 apart from the others) and every run's seconds by phase (--stats: G-buffer,
records, shading, ...; the temporal run's reprojection and test of expired records' use too).

--suite runs the clips of docs/lab/temporal-caching.md one after the other (the options above
but --scene, --frames, --slow, --width and --height ignored): the walkthrough (frames 0–47 at
--suite-size), moving-sphere (0–23), moving-sphere 8× slower, moving-light (0–15 at 128 × 96).

The clock (--clock): `cpu` (default), the CPU seconds (user + system) of the radcache processes,
which other processes on a shared machine barely change; or `wall`, the render phase of --stats.
Per-frame caching in one `--frames` run draws the same random streams every frame (records land
in the same places while nothing moves), so its flicker is that of a renderer whose streams do
not depend on the frame; that is the baseline here.

Usage: tools/bench/temporal.py [--scene scenes/moving-sphere] [--method ic|rc]
           [--reference DIR/frame####.exr] [--frames 0:11] [--width 128]
           [--height 128] [--spp 16] [--ladder "1024 512 256"] [--options "--ic-bounces 1"]
           [--temporal-options "--temporal-accuracy 0.05"] [--slow K] [--clock cpu]
           [--chart FILE.png] [--suite] [--suite-size 128]
           [--out build/bench/temporal] [-- extra radcache render options, e.g. --device 0:0]
Writes OUT/temporal.json and prints a table. Python 3 standard library (matplotlib for --chart).
"""

import argparse
import json
import math
import os
import shlex
import subprocess
import sys

from radcache_tools import ROOT
from radcache_tools import references
from radcache_tools.arguments import frame_range
from radcache_tools.arguments import parse_with_extra
from radcache_tools.radcache import cpu_seconds, run


def render(scene, pattern, options, clock):
    """Renders a frame sequence; its seconds on `clock` and its --stats."""
    stats_path = os.path.join(os.path.dirname(pattern), os.path.basename(pattern).split("#")[0]
                              + "stats.json")
    before = cpu_seconds()
    run(["render", scene, "-o", pattern, "--stats", stats_path, "--quiet"] + options)
    cpu = cpu_seconds() - before
    with open(stats_path) as f:
        stats = json.load(f)
    return (cpu if clock == "cpu" else stats["seconds"]["render"]), stats


def absolute_paths(node, scene_dir):
    """Every "file" and "filename" value under `node` made absolute (relative to scene_dir)."""
    if isinstance(node, dict):
        for key, value in node.items():
            if key in ("file", "filename") and isinstance(value, str) and not os.path.isabs(value):
                node[key] = os.path.normpath(os.path.join(scene_dir, value))
            else:
                absolute_paths(value, scene_dir)
    elif isinstance(node, list):
        for value in node:
            absolute_paths(value, scene_dir)


def slowed_scene(scene, factor, out_dir):
    """A copy of `scene` whose animation runs `factor` times slower (see --slow); its path."""
    try:
        document = references.load_scene_json(scene)
    except references.ReferenceError as e:
        sys.exit("--slow: %s" % e)
    absolute_paths(document, os.path.dirname(os.path.abspath(scene)))
    animation = document.get("animation")
    if not animation:
        sys.exit("--slow: %s has no animation" % scene)
    for key in ("frame_start", "frame_end"):
        if key in animation:
            animation[key] *= factor
    for track in animation.get("tracks", []):
        for keyframe in track.get("keyframes", []):
            keyframe["frame"] *= factor
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, "scene.json")
    with open(path, "w") as f:
        json.dump(document, f, indent=1)
    return path


def every_kth_frame(pattern, frames, factor):
    """Links OUT/slow/kth####.exr -> frame K·j of `pattern` for each j of `frames` (A:B)."""
    first, last = (int(x) for x in frames.split(":"))
    linked = os.path.join(os.path.dirname(pattern), "slow", "kth####.exr")
    os.makedirs(os.path.dirname(linked), exist_ok=True)
    for j in range(first, last + 1):
        link = linked.replace("####", "%04d" % j)
        if os.path.lexists(link):
            os.remove(link)
        os.symlink(os.path.abspath(pattern.replace("####", "%04d" % (factor * j))), link)
    return linked


def reference_step(reference, frames):
    """K where the references are every K-th frame from the clip's first (1: every frame)."""
    first, last = (int(x) for x in frames.split(":"))
    for k in range(1, last - first + 1):
        if os.path.exists(reference.replace("####", "%04d" % (first + k))):
            return k
    return 1


def link_frames(pattern, numbers, folder):
    """Links folder/f####.exr, #### = 0, 1, ..., to frames `numbers` of `pattern`; its pattern."""
    linked = os.path.join(folder, "f####.exr")
    os.makedirs(folder, exist_ok=True)
    for j, number in enumerate(numbers):
        link = linked.replace("####", "%04d" % j)
        if os.path.lexists(link):
            os.remove(link)
        os.symlink(os.path.abspath(pattern.replace("####", "%04d" % number)), link)
    return linked


def time_split(stats):
    """Where a run's time went, summed over its frames (--stats: each frame's seconds by phase,
    and with --temporal the reprojection and the test of expired records' use)."""
    split = {}
    for frame in stats.get("frames", []):
        for key, value in frame.get("seconds", {}).items():
            split[key] = split.get(key, 0.0) + value
        seconds = frame.get("temporal", {}).get("seconds", {})
        for key in ("reprojection", "usage"):
            split[key] = split.get(key, 0.0) + seconds.get(key, 0.0)
    return split


def sequence_errors(pattern, reference, frames, layer):
    """Means over the clip of `compare --frames` on `layer`, and its per-frame rows."""
    json_path = pattern.replace("####", "") + "." + layer + ".json"
    run(["compare", "--frames", frames, pattern, reference, "--aov", layer, "--json", json_path])
    with open(json_path) as f:
        result = json.load(f)
    return result["mean"], json_path


def measure(label, scene, pattern, options, args, slow=1):
    """Renders and compares one run; with slow > 1, the slowed clip (--slow) every slow-th frame."""
    seconds, stats = render(scene, pattern, options, args.clock)
    compared = every_kth_frame(pattern, args.frames, slow) if slow > 1 else pattern
    reference, frames = args.reference, args.frames
    if args.step > 1:
        first, last = (int(x) for x in args.frames.split(":"))
        numbers = list(range(first, last + 1, args.step))
        base = os.path.join(os.path.dirname(pattern), "kth", os.path.basename(pattern)[:-8])
        compared = link_frames(compared, numbers, base)
        reference = link_frames(args.reference, numbers, os.path.join(args.out, "kth", "ref"))
        frames = "0:%d" % (len(numbers) - 1)
    indirect, indirect_json = sequence_errors(compared, reference, frames, "indirect")
    beauty, _ = sequence_errors(compared, reference, frames, "beauty")
    row = {"label": label, "options": options, "seconds": seconds,
           "indirect_relmse": indirect["relmse"], "indirect_temporal": indirect["temporal_error"],
           "beauty_relmse": beauty["relmse"], "beauty_relmse_net": beauty["relmse_net"],
           "beauty_temporal": beauty["temporal_error"],
           "beauty_temporal_net": beauty["temporal_error_net"], "compare_json": indirect_json}
    temporal = [f.get("temporal") for f in stats.get("frames", []) if f.get("temporal")]
    if temporal:
        row["records_computed"] = sum(t["created"] + t["recomputed"] for t in temporal)
        row["records_per_frame"] = [t["created"] + t["recomputed"] for t in temporal]
        row["records_serving"] = [t["records"] for t in temporal]
        row["mean_new_lifespan"] = [t["mean_new_lifespan"] for t in temporal]
        later = row["records_per_frame"][1:]
        print("  %-28s first-level records computed: frame 0 %d, later frames %.1f a frame "
              "(serving %d at the end)"
              % ("", row["records_per_frame"][0], sum(later) / max(1, len(later)),
                 row["records_serving"][-1]), flush=True)
        radiance = [t["radiance"] for t in temporal if "radiance" in t]
        if radiance:
            row["radiance_records_computed"] = sum(r["created"] + r["recomputed"]
                                                   for r in radiance)
    row["time_split"] = time_split(stats)
    print("  %-28s seconds by phase: %s" % ("", ", ".join(
        "%s %.1f" % (key, value) for key, value in sorted(row["time_split"].items()))), flush=True)
    print("  %-28s %8.1f s  indirect relMSE %.3g  temporal %.3g  beauty relMSE %.3g"
          % (label, seconds, row["indirect_relmse"], row["indirect_temporal"],
             row["beauty_relmse"]), flush=True)
    return row


def log_interpolate(x, x0, x1, y0, y1):
    if x0 == x1:
        return y0
    f = (math.log(x) - math.log(x0)) / (math.log(x1) - math.log(x0))
    return math.exp(math.log(y0) + f * (math.log(y1) - math.log(y0)))


def time_at_error(error, ladder):
    """Per-frame caching's time at `error` and how it was found: "=", "≥" or "≤" (a bound on the
    speed-up it gives)."""
    runs = sorted(ladder, key=lambda r: r["indirect_relmse"])
    if error <= runs[0]["indirect_relmse"]:
        return runs[0]["seconds"], "≥"
    if error >= runs[-1]["indirect_relmse"]:
        return runs[-1]["seconds"], "≤"
    for a, b in zip(runs, runs[1:]):
        if a["indirect_relmse"] <= error <= b["indirect_relmse"]:
            return log_interpolate(error, a["indirect_relmse"], b["indirect_relmse"],
                                   a["seconds"], b["seconds"]), "="
    return runs[-1]["seconds"], "≤"


def temporal_error_at_time(seconds, ladder, key):
    """Per-frame caching's temporal error at `seconds`, and whether runs bracket it."""
    runs = sorted(ladder, key=lambda r: r["seconds"])
    below = [r for r in runs if r["seconds"] <= seconds]
    above = [r for r in runs if r["seconds"] >= seconds]
    if below and above:
        a, b = below[-1], above[0]
        return log_interpolate(seconds, a["seconds"], b["seconds"], a[key], b[key]), True
    nearest = below[-1] if below else above[0]
    return nearest[key], False


def chart(path, rows, args):
    command = [sys.executable, os.path.join(ROOT, "tools", "flicker_chart.py"), "--reference",
               args.reference, "--frames", args.frames, "--aov", "indirect", "--out", path,
               "--title", "%s, frames %s, indirect layer" % (os.path.basename(args.scene_dir),
                                                           args.frames)]
    for row in rows:
        command.append("%s=%s" % (row["label"], row["compare_json"]))
    subprocess.run(command, check=True)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=os.path.join(ROOT, "scenes", "moving-sphere"))
    parser.add_argument("--method", choices=["ic", "rc"], default="ic")
    parser.add_argument("--reference", default="",
                        help="the references' pattern (default SCENE/reference/frame####.exr)")
    parser.add_argument("--frames", default="0:11", type=frame_range)
    parser.add_argument("--width", type=int, default=128)
    parser.add_argument("--height", type=int, default=128)
    parser.add_argument("--spp", type=int, default=16)
    parser.add_argument("--ladder", default="1024 512 256",
                        help="per-frame ic's hemisphere rays per record, the first the temporal "
                             "render's own")
    parser.add_argument("--options", default="", help="options of every render (quoted)")
    parser.add_argument("--temporal-options", default="",
                        help="options of the temporal render only (quoted)")
    parser.add_argument("--slow", type=int, default=1,
                        help="the temporal run on the animation this many times slower")
    parser.add_argument("--clock", choices=["cpu", "wall"], default="cpu")
    parser.add_argument("--chart", default="", help="write the flicker chart here (.png)")
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "temporal"))
    parser.add_argument("--suite", action="store_true",
                        help="the walkthrough, moving-sphere, its 8x slow clip and moving-light")
    parser.add_argument("--suite-size", type=int, default=128,
                        help="--suite: the walkthrough's and moving-sphere's width and height")
    args, extra = parse_with_extra(parser, argv)
    if args.suite:
        return suite(args, argv)
    args.scene_dir = args.scene if os.path.isdir(args.scene) else os.path.dirname(args.scene)
    scene = os.path.join(args.scene_dir, "scene.json")
    args.reference = args.reference or os.path.join(args.scene_dir, "reference", "frame####.exr")
    if args.slow < 1:
        sys.exit("--slow: %d is not a positive integer" % args.slow)
    args.step = reference_step(args.reference, args.frames)
    if args.step > 1 and args.slow > 1:
        sys.exit("--slow: the references of %s are every %d-th frame" % (scene, args.step))
    ladder_rays = [int(n) for n in args.ladder.split()]
    rays_option = "--ic-rays" if args.method == "ic" else "--rc-rays"
    common = ["--method", args.method, "--frames", args.frames, "--width", str(args.width), "--height",
              str(args.height), "--spp", str(args.spp), "--aovs", "beauty,indirect"] \
        + shlex.split(args.options) + extra
    os.makedirs(args.out, exist_ok=True)
    out = lambda name: os.path.join(args.out, name)
    run(["render", scene, "-o", out("warm.exr"), "--quiet", "--method", "ic", "--width", "16",
         "--height", "16", "--spp", "1", "--ic-rays", "64"] + extra)

    print("%s, frames %s at %dx%d, %d spp (%s clock):" % (os.path.relpath(scene, ROOT),
                                                        args.frames, args.width, args.height,
                                                        args.spp, args.clock))
    first, last = (int(x) for x in args.frames.split(":"))
    temporal_scene = scene
    temporal_common = common
    if args.slow > 1:
        temporal_scene = slowed_scene(scene, args.slow, out("slow"))
        slow_frames = "%d:%d" % (args.slow * first, args.slow * last)
        temporal_common = list(common)
        temporal_common[common.index("--frames") + 1] = slow_frames
        print("  temporal run on %s, frames %s (every %d-th compared)"
              % (temporal_scene, slow_frames, args.slow))
    temporal = measure("temporal %s, %d rays" % (args.method, ladder_rays[0]), temporal_scene,
                       out("tc####.exr"),
                       temporal_common + [rays_option, str(ladder_rays[0]), "--temporal"]
                       + shlex.split(args.temporal_options), args, args.slow)
    ladder = [measure("per-frame %s, %d rays" % (args.method, rays), scene,
                      out("%s%d-####.exr" % (args.method, rays)),
                      common + [rays_option, str(rays)], args) for rays in ladder_rays]
    if args.slow > 1:
        scale = (args.slow * (last - first) + 1) / (last - first + 1)
        for row in ladder:
            row["referenced_frames_seconds"] = row["seconds"]
            row["seconds"] *= scale
        print("  per-frame times scaled by %.3f to the slow clip's %d frames"
              % (scale, args.slow * (last - first) + 1))

    per_frame_time, bound = time_at_error(temporal["indirect_relmse"], ladder)
    speedup = per_frame_time / temporal["seconds"]
    flicker, bracketed = temporal_error_at_time(temporal["seconds"], ladder, "indirect_temporal")
    flicker_ratio = flicker / temporal["indirect_temporal"]
    same = ladder[0]
    result = {"scene": scene, "method": args.method, "frames": args.frames, "slow": args.slow,
              "resolution": [args.width, args.height],
              "spp": args.spp, "clock": args.clock, "extra_options": extra,
              "temporal": temporal, "ladder": ladder,
              "speedup_at_equal_indirect_relmse": {"value": speedup, "bound": bound,
                                                   "per_frame_seconds": per_frame_time},
              "reference_step": args.step,
              "flicker_at_equal_time": {"per_frame": flicker, "bracketed": bracketed,
                                        "ratio": flicker_ratio} if args.slow == 1 else None,
              "same_settings": {"speedup": same["seconds"] / temporal["seconds"],
                                "indirect_relmse_ratio":
                                    temporal["indirect_relmse"] / same["indirect_relmse"],
                                "flicker_ratio":
                                    same["indirect_temporal"] / temporal["indirect_temporal"]
                                    if args.slow == 1 else None}}
    with open(out("temporal.json"), "w") as f:
        json.dump(result, f, indent=2)
    print("same settings: per-frame / temporal time %.2f×, indirect relMSE temporal / per-frame "
          "%.2f" % (result["same_settings"]["speedup"],
                    result["same_settings"]["indirect_relmse_ratio"])
          + (", temporal error per-frame / temporal %.2f×" % result["same_settings"]["flicker_ratio"]
             if args.slow == 1 else ""))
    print("speed-up at equal indirect relMSE: %s %.2f× (per-frame %.1f s against %.1f s)"
          % ("" if bound == "=" else bound, speedup, per_frame_time, temporal["seconds"]))
    if args.slow == 1:
        print("temporal error%s at equal time: per-frame %.3g against %.3g: %.2f× lower%s"
              % ("" if args.step == 1 else " between frames %d apart (not flicker)" % args.step,
                 flicker, temporal["indirect_temporal"], flicker_ratio,
                 "" if bracketed else " (nearest per-frame run, not interpolated)"))
    if args.chart and args.slow == 1 and args.step == 1:
        chart(args.chart, [temporal] + ladder, args)
    return 0


def suite(args, argv):
    """--suite: main() once per clip, each into OUT/NAME."""
    size = str(args.suite_size)
    clips = [("walkthrough", ["--scene", os.path.join(ROOT, "scenes", "walkthrough"),
                              "--frames", "0:47", "--width", size, "--height", size]),
             ("moving-sphere", ["--scene", os.path.join(ROOT, "scenes", "moving-sphere"),
                                "--frames", "0:23", "--width", size, "--height", size]),
             ("moving-sphere-slow8", ["--scene", os.path.join(ROOT, "scenes", "moving-sphere"),
                                      "--frames", "0:23", "--width", size, "--height", size,
                                      "--slow", "8"]),
             ("moving-light", ["--scene", os.path.join(ROOT, "scenes", "moving-light"),
                               "--frames", "0:15", "--width", "128", "--height", "96"])]
    # The options given, less --suite's own and those each clip sets.
    own = {"--suite": 0, "--suite-size": 1, "--scene": 1, "--frames": 1, "--slow": 1,
           "--width": 1, "--height": 1, "--out": 1, "--reference": 1}
    kept = []
    i = 0
    while i < len(argv):
        name = argv[i].split("=")[0]
        if name == "--":
            kept += argv[i:]
            break
        if name in own:
            i += 1 + (own[name] if "=" not in argv[i] else 0)
            continue
        kept.append(argv[i])
        i += 1
    status = 0
    for name, options in clips:
        status |= main(options + ["--out", os.path.join(args.out, name)] + kept)
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
