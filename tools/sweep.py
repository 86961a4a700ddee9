#!/usr/bin/env python3
"""Speed-versus-accuracy sweep of radcache's methods on one scene (DESIGN.md §7).

Runs every method over its quality knobs, each point --repeats times, measures each image
against the scene's reference (RMSE and relMSE through `radcache compare`, HDR-FLIP through the
flip-evaluator package when it is installed: without it the flip column stays empty, with one
warning) and writes

  OUT/sweep.csv, OUT/sweep.json   one row per point, the columns below
  OUT/error-vs-time.png           log-log relMSE of the image against the median render time,
                                  one curve per method and setting, a horizontal bar over each
                                  point from its fastest to its slowest repeat, the Pareto front
                                  over all points marked
  OUT/flip-vs-time.png            the same for the mean HDR-FLIP of the image (with flip-evaluator)
  OUT/indirect-error-vs-time.png  the same for the indirect layer (methods that write it)
  OUT/index.html                  the charts, equal-time crops of every curve beside the
                                  reference's, and false-colour relMSE images

Methods and knobs come from radcache's option tables, read once at start through the same
radcache: the methods, in the registry's order, and each one's quality knobs (options that trade
time for accuracy, each with its default, range or choices and the direction that buys accuracy)
from `radcache render --list-knobs --json`, the options each table declares from `radcache
reference`. --methods takes every method with knobs (a method without any, such as normals, is
not swept), ic-ivg (ic with its --ic-ivg flag: ic's records' hemisphere rays read the irradiance
vector grid) or all. Each method has curated curves, below; every option they vary is checked
against the method's knobs at start and the sweep fails naming the method and the option when
its table does not mark it a knob (what they set and do not vary, --ic-ivg and decomposition's
--alpha, must be declared by the table), so the sweep and the tables cannot drift. --spp, which
every curve sets and pt's varies, is the render's own setting, not a method's knob. A method the
tables have and the sweep has no curated curves for is swept along a generated ladder (below) of
each of its knobs that has one.

The curated curves: pt (--pt-spp); auto (`--method auto`, one point per --auto-time budget:
the method, knobs and samples it chooses itself, docs/auto.md); ic (one curve per --ic-rays x --ic-spp x --ic-min-spacing,
--ic-accuracy along it); ic-ivg (--ic-accuracy at the first --ic-spp, --ic-rays and
--ic-min-spacing); rc (radiance caching for glossy lobes beside ic's defaults for diffuse ones:
one curve per --rc-rays, --ic-accuracy along it at the first --ic-spp); sdrc (spatial
directional radiance caching for glossy lobes, the same way: one curve per --sdrc-interp,
--ic-accuracy along it at the first --ic-spp); ivg (one curve per --ivg-grid, --ivg-photons
along it, at --ivg-spp camera samples); ivg-gather (--gather-rays per camera sample at
--gather-spp camera samples, the grid at its defaults); decomposition (irradiance
decomposition, docs/decomposition.md: one curve per --decomp-rays x --decomp-alpha, the
smallest cluster --decomp-cluster along it, at --decomp-spp camera samples; its knobs are named
in the curve and setting columns). A grid is auto (about 32k vertices), auto*K (K times auto's
voxels per axis, read off the untimed warm-up render) or NxMxK; a min spacing is `default` (the
method's) or what --ic-min-spacing takes (8px, 5u).

Ladders. --ladder METHOD:OPTION=V1,V2,... (repeatable) adds one curve of METHOD (or ic-ivg)
with its quality knob OPTION at each value in turn, every other option at its default and
--spp at --ladder-spp (default: the scene's): method column METHOD, curve "METHOD OPTION
ladder", setting "OPTION=VALUE" (and the column of that name, ic_rays for --ic-rays, where the
CSV has one). Without values (--ladder METHOD:OPTION) the ladder is generated from the table: 4
values from the default towards accuracy, x2 a step for an "increase" knob and /1.5 for a
"decrease" one (integers rounded), clamped to the knob's range and de-duplicated; a choice knob
takes each of its choices. A knob whose default depends on other options (--photons: 8 per grid
vertex) or that is not a number (a length, a resolution, auto) needs its values. An option that
is not a knob of METHOD, an unknown method, and a value radcache's own parser refuses (each
value is checked before anything renders) stop the sweep with one line and no output. E.g.
`--ladder ic:--ic-rays` renders ic at 1024, 2048, 4096 and 8192 rays per record;
`--ladder ivg:--photons=65536,262144`; `--ladder ivg:--grid=auto,auto*2`. With --ladder and no
--methods only the ladders are drawn.

The defaults reach settings tight enough that each caching method's error keeps falling:
ic's accuracy goes to 0.15 on curves of 1024 and 4096 rays per record, each with the method's
min spacing and with 2px (a min spacing bounds the records' radius from below, so without a
smaller one a tighter accuracy adds few records; the rays set the records' own noise, the floor
of a curve), at the method's 4 camera samples; ivg's photons go to 4M on the auto grid and on
auto*2 (8x the vertices: the auto grid's discretisation is the floor of its curve).

Repeats. Every point is rendered --repeats times (default 3), in rounds over all points so that
a burst of load on the machine lands on one repeat of several points rather than on every
repeat of one. The seed is the same, so the images must be bitwise identical: every repeat's
pixels (SHA-1 of `iinfo --hash`, from openimageio-tools) are checked against the first's, with
its ray and record counts, and the sweep fails naming the point if one differs. The errors are
measured once, on the first repeat's image. The time columns are the median over the repeats
(the mean of the middle two for an even count) and their _min and _max the fastest and slowest.

Columns: scene, frame, method, curve, setting, spp, accuracy, ic_rays, ic_min_spacing, rc_rays, sdrc_interp,
photons, grid, gather_rays, repeats, wall_seconds, wall_seconds_min, wall_seconds_max,
render_seconds, render_seconds_min, render_seconds_max, kernel_seconds, kernel_seconds_min,
kernel_seconds_max, compile_seconds, denoise_seconds, rmse, relmse, relmse_net, flip,
indirect_relmse, records, device, image.

relmse_net is the image's relMSE net of the reference's own noise (`radcache compare`: relmse
minus the mean of (stddev^2/spp_ref)/(r^2+0.01)); empty unless the reference has a stddev layer
and its sample count is known (`spp` of REF.stats.json or REF.json beside it, REF the reference's
name without .exr; every shipped reference has its REF.json). It may be slightly negative for an
image as good as the reference.

Times. render_seconds is the render phase of `radcache render --stats` (G-buffer to final
image; scene loading, device start-up and image writing excluded); its median is the chart's
time axis. wall_seconds is the whole process; kernel_seconds the sum of the kernels' device
times from OpenCL profiling events. Kernel compilation is excluded: one untimed render per
method at the sweep's resolution and one sample per pixel first fills the kernel binary cache
and lets the device generate code for the launch shapes, and compile_seconds (the timed runs'
program builds, from that cache; median) says what was left. Peers (POV-Ray, `--povray`) run once
(repeats 1), timed by the wall clock of the whole peer process, parsing included.

Peers and denoised curves (tools/sweep_peers.py; both optional: without their Python packages
the sweep skips their curves with one warning, as it does FLIP). --denoise passes every radcache
point's image through OIDN with its albedo and normal layers (tools/denoise.py) and adds it as
the method METHOD+oidn, curve "CURVE +oidn": its times are the point's plus the denoise step's
(reading, OIDN and writing the EXR, OIDN's device warmed by one untimed denoise first), in the
column denoise_seconds; its indirect_relmse stays empty (only the beauty is denoised).
--mitsuba [SPP ...] adds Mitsuba 3's path tracer (tools/peers/mitsuba/ladder.py) at those samples
per pixel (default 4 16 64 256), method mitsuba: render_seconds is mi.render alone, wall_seconds
the whole process; a scene the exporter refuses (a material without an exact counterpart) gets
no Mitsuba curve and one warning naming it. Every chart also has a FLIP twin (flip-vs-time.png).

Usage: tools/sweep.py SCENE [--frame F] [--reference EXR] [--repeats N] [--methods pt ic ...|all]
           [--ladder METHOD:OPTION[=V1,V2,...] ...] [--ladder-spp N]
           [--pt-spp 1 2 4 ...] [--ic-accuracy ...] [--ic-rays ...] [--ic-spp ...]
           [--ic-min-spacing ...] [--ivg-photons ...] [--ivg-grid ...] [--ivg-spp N]
           [--gather-rays ...] [--gather-spp N] [--decomp-alpha ...] [--decomp-cluster ...]
           [--decomp-rays ...] [--decomp-spp N] [--width N --height N]
           [--povray [SETTING ...]] [--mitsuba [SPP ...]] [--denoise] [--out DIR]
           [-- extra radcache render options]
SCENE is a scene directory or its scene.json. The reference defaults to the scene's shipped one
for the frame (tools/references.py: reference.exr beside it, or reference/frameFFFF.exr of an
animated scene); --frame F (default: the scene's first) renders that frame of an animated scene.
The radcache executable is build/radcache, or $RADCACHE when set. At the defaults a sweep of one
512-pixel scene with every method is estimated at 35-40 minutes on 2 CPU cores (3 repeats;
docs/benchmarks.md, "Error against time", from timed single points).
"""

import argparse
import collections
import csv
import datetime
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys

from radcache_tools import ROOT, radcache, references
from radcache_tools.arguments import parse_with_extra, positive_int
from radcache_tools.error import compare, has_layer
import sweep_knobs
import sweep_peers
import sweep_report

TIMES = ["wall_seconds", "render_seconds", "kernel_seconds"]
COLUMNS = ["scene", "frame", "method", "curve", "setting", "spp", "accuracy", "ic_rays",
           "ic_min_spacing", "rc_rays", "sdrc_interp", "photons", "grid", "gather_rays", "repeats"] + [
           "%s%s" % (t, suffix) for t in TIMES for suffix in ("", "_min", "_max")] + [
           "compile_seconds", "denoise_seconds", "rmse", "relmse", "relmse_net", "flip",
           "indirect_relmse", "records", "device", "image"]
# The columns a point's knobs fill (the rest come from its --stats); a ladder of the option
# --NAME-WITH-DASHES fills the column NAME_WITH_DASHES when there is one.
KNOB_COLUMNS = ["spp", "accuracy", "ic_rays", "ic_min_spacing", "rc_rays", "sdrc_interp",
                "gather_rays"]
# ic's flag that makes the ic-ivg curves: its records' hemisphere rays read the grid.
IVG_FLAG = "--ic-ivg"
# The curves a sweep without --methods and --ladder draws (checked against the registry like any
# --methods).
DEFAULT_METHODS = ["pt", "auto", "ic"]
GRID_FORM = re.compile(r"^(auto|auto\*(\d+(\.\d+)?)|\d+x\d+x\d+)$")
SPACING_FORM = re.compile(r"^(default|\d+(\.\d+)?(px|u)?)$")
LENGTH_FORM = re.compile(r"^\d*\.?\d+(%|u)?$")
# The Mitsuba peer's samples per pixel when --mitsuba names none.
MITSUBA_SPP = [4, 16, 64, 256]


def fail(message):
    sys.exit("sweep: " + message)


def flip_available():
    """Whether the flip-evaluator package can be imported (the flip column needs it)."""
    try:
        import flip_evaluator  # noqa: F401
    except ImportError:
        return False
    return True


def flip_error(image, reference):
    """Mean HDR-FLIP of the beauty channels (flip-evaluator reads R, G, B of an EXR); "" when
    flip-evaluator is not installed."""
    if not flip_available():
        return ""
    import flip_evaluator
    _, mean, _ = flip_evaluator.evaluate(reference, image, "HDR", applyMagma=False)
    return float(mean)


def pixel_hash(image):
    """SHA-1 of an image's pixels, every channel (`iinfo --hash`): the EXR header also holds the
    time of writing, so the files' bytes differ between identical renders."""
    result = subprocess.run(["iinfo", "--hash", image], capture_output=True, text=True)
    found = re.search(r"SHA-1:\s*([0-9A-Fa-f]+)", result.stdout)
    if result.returncode != 0 or not found:
        fail("iinfo --hash %s failed:\n%s%s" % (image, result.stdout, result.stderr))
    return found.group(1)


def image_size(image):
    """(width, height) of an image from `iinfo`, or None when it cannot say."""
    if not shutil.which("iinfo"):
        return None
    result = subprocess.run(["iinfo", image], capture_output=True, text=True)
    found = re.search(r":\s*(\d+)\s*x\s*(\d+)", result.stdout)
    return (int(found.group(1)), int(found.group(2))) if found else None


def check_reference_size(reference, width, height):
    """Fails before any render when --width/--height differ from the reference's size."""
    size = image_size(reference)
    if size is None or (width or size[0], height or size[1]) == size:
        return
    fail("the reference %s is %dx%d; at --width/--height %sx%s pass a reference of that size "
         "(--reference)" % (reference, size[0], size[1], width or size[0], height or size[1]))


def scene_paths(scene, reference, frame):
    """The scene's JSON, its reference for the frame and the frame (None: the scene's first)."""
    scene_json = os.path.join(scene, "scene.json") if os.path.isdir(scene) else scene
    if not os.path.isfile(scene_json):
        fail("scene not found: %s" % scene_json)
    try:
        start, end = references.frame_range(scene_json)
        if frame is not None and not start <= frame <= end:
            fail("--frame %d: %s has frames %d:%d" % (frame, scene_json, start, end))
        reference = reference or references.reference_path(os.path.dirname(scene_json), frame)
    except references.ReferenceError as e:
        fail(str(e))
    if not os.path.isfile(reference):
        fail("reference not found: %s (pass --reference)" % reference)
    frame = start if frame is None else frame
    return os.path.abspath(scene_json), os.path.abspath(reference), frame, end > start


def render(scene, image, options):
    """One timed `radcache render`; returns the wall seconds and the --stats JSON."""
    return radcache.timed_render(scene, image, options, tool="sweep")


def grid_option(grid, auto_cells):
    """--grid's value for a sweep grid: auto*K becomes K times the auto grid's voxels."""
    found = GRID_FORM.match(grid)
    if found is None or found.group(2) is None:
        return grid
    if auto_cells is None:
        fail("grid %s: no warm-up render built the auto grid to scale" % grid)
    return "x".join(str(max(1, round(float(found.group(2)) * c))) for c in auto_cells)


def spacing_options(spacing):
    return [] if spacing == "default" else ["--ic-min-spacing", spacing]


def spacing_label(spacing):
    return "" if spacing == "default" else ", min spacing %s" % spacing


def auto_runs(args, auto_cells):
    """--method auto at each --auto-time budget: its own choice of method, knobs and samples."""
    return [("auto", "auto", "time=%g" % budget, {"time": budget},
             ["--method", "auto", "--time", "%g" % budget])
            for budget in args.auto_time]


def pt_runs(args, auto_cells):
    return [("pt", "pt", "spp=%d" % spp, {"spp": spp}, ["--method", "pt", "--spp", str(spp)])
            for spp in args.pt_spp]


def ic_runs(args, auto_cells):
    runs = []
    for rays in args.ic_rays:
        for spp in args.ic_spp:
            for spacing in args.ic_min_spacing:
                curve = "ic %d rays, %d spp%s" % (rays, spp, spacing_label(spacing))
                for accuracy in args.ic_accuracy:
                    runs.append(("ic", curve, "accuracy=%g rays=%d spp=%d spacing=%s" % (
                                     accuracy, rays, spp, spacing),
                                 {"spp": spp, "accuracy": accuracy, "ic_rays": rays,
                                  "ic_min_spacing": spacing},
                                 ["--method", "ic", "--spp", str(spp), "--accuracy",
                                  str(accuracy), "--ic-rays", str(rays)] +
                                 spacing_options(spacing)))
    return runs


def ic_ivg_runs(args, auto_cells):
    rays, spp, spacing = args.ic_rays[0], args.ic_spp[0], args.ic_min_spacing[0]
    return [("ic-ivg", "ic + grid, %d spp%s" % (spp, spacing_label(spacing)),
             "accuracy=%g rays=%d spp=%d spacing=%s" % (accuracy, rays, spp, spacing),
             {"spp": spp, "accuracy": accuracy, "ic_rays": rays, "grid": "auto",
              "ic_min_spacing": spacing},
             ["--method", "ic", IVG_FLAG, "--spp", str(spp), "--accuracy", str(accuracy),
              "--ic-rays", str(rays)] + spacing_options(spacing))
            for accuracy in args.ic_accuracy]


def rc_runs(args, auto_cells):
    spp = args.ic_spp[0]
    return [("rc", "rc %d rays, %d spp" % (rays, spp),
             "accuracy=%g rc_rays=%d spp=%d" % (accuracy, rays, spp),
             {"spp": spp, "accuracy": accuracy, "rc_rays": rays},
             ["--method", "rc", "--spp", str(spp), "--accuracy", str(accuracy), "--rc-rays",
              str(rays)])
            for rays in args.rc_rays for accuracy in args.ic_accuracy]


def sdrc_runs(args, auto_cells):
    spp = args.ic_spp[0]
    return [("sdrc", "sdrc %d directions, %d spp" % (interp, spp),
             "accuracy=%g sdrc_interp=%d spp=%d" % (accuracy, interp, spp),
             {"spp": spp, "accuracy": accuracy, "sdrc_interp": interp},
             ["--method", "sdrc", "--spp", str(spp), "--accuracy", str(accuracy),
              "--sdrc-interp", str(interp)])
            for interp in args.sdrc_interp for accuracy in args.ic_accuracy]


def ivg_runs(args, auto_cells):
    return [("ivg", "ivg, grid %s, %d spp" % (grid, args.ivg_spp),
             "photons=%d grid=%s" % (photons, grid), {"spp": args.ivg_spp, "photons": photons},
             ["--method", "ivg", "--spp", str(args.ivg_spp), "--photons", str(photons),
              "--grid", grid_option(grid, auto_cells)])
            for grid in args.ivg_grid for photons in args.ivg_photons]


def gather_runs(args, auto_cells):
    spp = args.gather_spp
    return [("ivg-gather", "ivg-gather, %d spp" % spp, "gather_rays=%d spp=%d" % (gathers, spp),
             {"spp": spp, "gather_rays": gathers},
             ["--method", "ivg-gather", "--spp", str(spp), "--gather-rays", str(gathers)])
            for gathers in args.gather_rays]


def decomposition_runs(args, auto_cells):
    """Irradiance decomposition: a curve per rays per cluster and alpha, the smallest cluster
    along it (its knobs live in the curve and setting columns)."""
    spp = args.decomp_spp
    return [("decomposition", "decomposition alpha %s, %d rays, %d spp" % (alpha, rays, spp),
             "alpha=%s cluster=%s rays=%d spp=%d" % (alpha, size, rays, spp), {"spp": spp},
             ["--method", "decomposition", "--spp", str(spp), "--alpha", alpha,
              "--decomp-cluster", size, "--decomp-rays", str(rays)])
            for rays in args.decomp_rays for alpha in args.decomp_alpha
            for size in args.decomp_cluster]


# The sweep's curated curves, by the name --methods takes: the method they render, the flags
# every point passes (a variant: ic-ivg is ic with --ic-ivg), the options their points vary (each
# must be a quality knob of the method's table), the other options they set (each must be
# declared by the table), and the points. Both lists are checked against the tables at start,
# so the sweep and the tables cannot drift. Every curve also sets --spp (pt's curve varies it):
# the render's own setting, which every method takes and no method's table declares.
# decomposition's --alpha is the near/far split of the model, not a trade of time for accuracy
# (the error is least near its default and grows either way, docs/lab/decomposition.md): its
# table does not mark it a knob.
Curated = collections.namedtuple("Curated", "method flags varies sets runs")
CURATED = collections.OrderedDict([
    ("pt", Curated("pt", [], [], [], pt_runs)),
    ("auto", Curated("auto", [], [], [], auto_runs)),
    ("ic", Curated("ic", [], ["--accuracy", "--ic-rays", "--ic-min-spacing"], [], ic_runs)),
    ("ic-ivg", Curated("ic", [IVG_FLAG], ["--accuracy", "--ic-rays", "--ic-min-spacing"], [],
                       ic_ivg_runs)),
    ("rc", Curated("rc", [], ["--accuracy", "--rc-rays"], [], rc_runs)),
    ("sdrc", Curated("sdrc", [], ["--accuracy", "--sdrc-interp"], [], sdrc_runs)),
    ("ivg", Curated("ivg", [], ["--photons", "--grid"], [], ivg_runs)),
    ("ivg-gather", Curated("ivg-gather", [], ["--gather-rays"], [], gather_runs)),
    ("decomposition", Curated("decomposition", [], ["--decomp-rays", "--decomp-cluster"],
                              ["--alpha"], decomposition_runs)),
])


def variants():
    """name -> (method, flags) of the curated curves that are not a method of their own."""
    return {name: (c.method, c.flags) for name, c in CURATED.items() if name != c.method}


def check_curated(tables):
    """Every curated curve against the tables: its method, the knobs it varies, what it sets."""
    for name, curated in CURATED.items():
        sweep_knobs.check_curated(name, curated.method, curated.varies,
                                  curated.flags + curated.sets, tables)


def sweepable(tables):
    """What --methods takes, in the registry's order: each method with quality knobs or a curated
    curve (pt's varies --spp, the render's own setting), its variants beside it."""
    names = []
    for method, knobs in tables.knobs.items():
        if knobs or method in CURATED:
            names += [method] + [v for v, (base, _) in variants().items() if base == method]
    return names


def selected_methods(requested, tables):
    """--methods in the registry's order ("all": every sweepable one); fails on a name radcache
    does not have, or a method without quality knobs."""
    names = sweepable(tables)
    for name in requested:
        if name in tables.knobs and name not in names:
            fail("--methods %s: its option table has no quality knobs, nothing to sweep" % name)
        if name != "all" and name not in names:
            fail("--methods %s: unknown method (radcache's methods with quality knobs and the "
                 "sweep's variants: %s, or all)" % (name, ", ".join(names)))
    return [n for n in names if n in requested or "all" in requested]


def method_of(name):
    """(method, flags) that render a sweep name (a method or a variant)."""
    return variants().get(name, (name, []))


def sweep_ladders(args, methods, tables):
    """The --ladder curves, then a generated ladder of each knob of a method with no curated
    curves."""
    try:
        ladders = [sweep_knobs.ladder(spec, tables, variants()) for spec in args.ladder]
        for name in methods:
            if name not in CURATED:
                generated = sweep_knobs.generated_ladders(name, *method_of(name), tables)
                if not generated:
                    fail("--methods %s: no curated curves and no knob with a generated ladder: "
                         "give one, --ladder %s:OPTION=V1,V2,..." % (name, name))
                ladders += generated
    except sweep_knobs.KnobError as e:
        fail(str(e))
    return ladders


def ladder_runs(ladder, args, auto_cells):
    """One curve: the ladder's option at each value, every other option at its default (--spp:
    --ladder-spp, else the scene's)."""
    curve = "%s %s ladder" % (ladder.name, ladder.option)
    column = ladder.option.lstrip("-").replace("-", "_")
    spp = ["--spp", str(args.ladder_spp)] if args.ladder_spp else []
    runs = []
    for value in ladder.values:
        given = grid_option(value, auto_cells) if ladder.knob["type"] == "resolution" else value
        runs.append((ladder.name, curve, "%s=%s" % (ladder.option, value),
                     {column: typed(value)} if column in KNOB_COLUMNS else {},
                     ["--method", ladder.method] + ladder.flags + [ladder.option, given] + spp))
    return runs


def typed(value):
    """A ladder's value for the CSV and JSON: an int or float where it is one."""
    for kind in (int, float):
        try:
            return kind(value)
        except ValueError:
            pass
    return value


def radcache_runs(args, methods, ladders, auto_cells):
    """(method, curve, setting, knobs, options) for every radcache point of the sweep."""
    runs = []
    for name in methods:
        if name in CURATED:
            runs += CURATED[name].runs(args, auto_cells)
    for ladder in ladders:
        runs += ladder_runs(ladder, args, auto_cells)
    return runs


def reads_grid(method, flags, tables):
    """Whether a method's renders build the irradiance vector grid: it has the grid's --photons
    knob, and takes it with --ic-ivg where its table has that flag (ic)."""
    return "--photons" in tables.knobs[method] and (
        IVG_FLAG not in tables.declared.get(method, ()) or IVG_FLAG in flags)


def warm_up(scene, out, names, tables, options):
    """Untimed: one render per method at the sweep's resolution and one sample per pixel fills
    the kernel binary cache and lets the device generate code for the launch shapes the timed
    runs use (PoCL does that on a shape's first launch). Returns the auto grid's voxels per axis
    (None when no method builds a grid)."""
    auto_cells = None
    for name in names:
        method, flags = method_of(name)
        warm = ["--method", method] + flags
        if reads_grid(method, flags, tables):
            warm += ["--photons", "1000"]
        _, stats = render(scene, os.path.join(out, "warm-%s.exr" % name),
                          warm + ["--spp", "1"] + options)
        grid = (stats.get("frames") or [{}])[0].get("grid")
        if grid:
            auto_cells = grid["cells"]
    return auto_cells


def timing(wall, stats):
    frame = stats["frames"][0] if stats.get("frames") else {}
    return {"wall_seconds": wall, "render_seconds": stats["seconds"]["render"],
            "kernel_seconds": sum(k["seconds"] for k in stats["kernels"].values()),
            "compile_seconds": sum(b["seconds"] for b in stats.get("program_builds", [])),
            "rays": stats["rays"], "records": frame.get("records", "")}


def check_repeat(name, setting, first, repeat, index):
    """Fails loudly unless a repeat rendered the first's image (same seed, same options)."""
    for key in ("hash", "rays", "records"):
        if repeat[key] != first[key]:
            fail("not deterministic: %s (%s): repeat %d's %s %s differs from repeat 1's %s" % (
                 name, setting, index + 1, "pixels (SHA-1)" if key == "hash" else key,
                 repeat[key], first[key]))


def run_points(scene, runs, out, options, repeats):
    """Renders every point `repeats` times, in rounds; returns the timings of each point's
    repeats and the first repeat's --stats. Only the first repeat's image is kept."""
    measured = [[] for _ in runs]
    first_stats = [None] * len(runs)
    for repeat in range(repeats):
        for index, (method, _, setting, _, run_options) in enumerate(runs):
            name = "%s-%02d" % (method, index)
            image = os.path.join(out, name + (".exr" if repeat == 0 else ".repeat.exr"))
            print("[repeat %d/%d] [%d/%d] %s %s" % (repeat + 1, repeats, index + 1, len(runs),
                                                    method, setting), flush=True)
            wall, stats = render(scene, image, run_options + options)
            result = timing(wall, stats)
            result["hash"] = pixel_hash(image) if repeats > 1 else ""
            if repeat == 0:
                first_stats[index] = stats
            else:
                check_repeat(name, setting, measured[index][0], result, repeat)
                os.remove(image)
                os.remove(os.path.splitext(image)[0] + ".stats.json")
            measured[index].append(result)
    return measured, first_stats


def time_columns(results):
    """Median, fastest and slowest of each time over a point's repeats."""
    row = {"repeats": len(results),
           "compile_seconds": statistics.median(r["compile_seconds"] for r in results)}
    for key in TIMES:
        values = [r[key] for r in results]
        row[key] = statistics.median(values)
        row[key + "_min"] = min(values)
        row[key + "_max"] = max(values)
    return row


def measure(row, image, reference, out, name):
    """Fills the error columns of a row; writes OUT/NAME.error.png."""
    error_png = os.path.join(out, name + ".error.png")
    beauty = compare(image, reference, os.path.join(out, name + ".compare.json"),
                     options=["--error-image", error_png], tool="sweep")
    row["rmse"] = beauty["rmse"]
    row["relmse"] = beauty["relmse"]
    # Net of the reference's noise: null in compare's JSON when it is not known.
    net = beauty.get("relmse_net")
    row["relmse_net"] = "" if net is None else net
    row["flip"] = flip_error(image, reference)
    row["indirect_relmse"] = ""
    if has_layer(image, "indirect") and has_layer(reference, "indirect"):
        indirect = compare(image, reference, os.path.join(out, name + ".indirect.json"),
                           "indirect", tool="sweep")
        row["indirect_relmse"] = indirect["relmse"]
    row["image"] = os.path.relpath(image, out)


def radcache_rows(runs, measured, first_stats, reference, out):
    rows = []
    for index, (method, curve, setting, knobs, _) in enumerate(runs):
        name = "%s-%02d" % (method, index)
        stats = first_stats[index]
        frame = stats["frames"][0] if stats.get("frames") else {}
        grid = frame.get("grid", {})
        row = {column: knobs.get(column, "") for column in KNOB_COLUMNS}
        row.update({"method": method, "curve": curve, "setting": setting,
                    "spp": knobs.get("spp", stats.get("spp", "")),
                    "grid": "x".join(str(c) for c in grid["cells"]) if grid else "",
                    "photons": grid.get("photons", ""), "records": frame.get("records", ""),
                    "device": stats["device"]})
        row.update(time_columns(measured[index]))
        row["denoise_seconds"] = ""
        measure(row, os.path.join(out, name + ".exr"), reference, out, name)
        rows.append(row)
    return rows


def povray_rows(args, scene, reference, out):
    """Runs the POV-Ray peer (tools/peers/povray) once and returns its rows."""
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
            seconds = float(peer["seconds"])
            row = {"method": "povray", "curve": "POV-Ray 3.7 radiosity",
                   "setting": peer["setting"], "spp": "", "accuracy": "", "ic_rays": "",
                   "ic_min_spacing": "", "rc_rays": "", "sdrc_interp": "", "photons": "", "grid": "", "gather_rays": "",
                   "repeats": 1, "kernel_seconds": "", "kernel_seconds_min": "",
                   "kernel_seconds_max": "", "compile_seconds": "", "records": "",
                   "denoise_seconds": "",
                   "device": "POV-Ray, %s threads" % peer["threads"]}
            for key in ("wall_seconds", "render_seconds"):
                row[key] = row[key + "_min"] = row[key + "_max"] = seconds
            measure(row, image, reference, out, name)
            rows.append(row)
    return rows


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
    parser.add_argument("--frame", type=int,
                        help="frame of an animated scene (default: its first)")
    parser.add_argument("--reference",
                        help="reference image (default: the scene's shipped one for the frame)")
    parser.add_argument("--repeats", type=int, default=3,
                        help="timed renders of every point (default 3; at least 1)")
    parser.add_argument("--methods", nargs="+", metavar="METHOD",
                        help="radcache's methods with quality knobs (render --list-knobs), in "
                             "its order, ic-ivg (ic with --ic-ivg) beside ic, or all (default: "
                             "%s; none with --ladder)" % " ".join(DEFAULT_METHODS))
    parser.add_argument("--ladder", action="append", default=[],
                        metavar="METHOD:OPTION[=V1,V2,...]",
                        help="one more curve: METHOD with its quality knob OPTION at each value "
                             "in turn, every other option at its default; without values, %d "
                             "from the knob's default towards accuracy (x%g or /%g a step, "
                             "within its range) or a choice knob's choices; repeatable" % (
                                 sweep_knobs.LADDER_STEPS, sweep_knobs.INCREASE_STEP,
                                 sweep_knobs.DECREASE_STEP))
    parser.add_argument("--ladder-spp", type=int,
                        help="--ladder curves' camera samples per pixel (default: the scene's)")
    parser.add_argument("--auto-time", nargs="+", type=float, default=[10, 30, 100],
                        help="auto's budgets (--time), one point each (default: %(default)s)")
    parser.add_argument("--pt-spp", nargs="+", type=int,
                        default=[1, 2, 4, 8, 16, 32, 64, 128, 256, 512],
                        help="pt's samples per pixel (default: %(default)s)")
    parser.add_argument("--ic-accuracy", nargs="+", type=float,
                        default=[0.6, 0.35, 0.25, 0.15],
                        help="ic's accuracy along each curve (default: %(default)s)")
    parser.add_argument("--ic-rays", nargs="+", type=int, default=[1024, 4096],
                        help="ic's hemisphere rays per record (default: %(default)s)")
    parser.add_argument("--ic-spp", nargs="+", type=int, default=[4],
                        help="ic's camera samples per pixel (default: %(default)s)")
    parser.add_argument("--ic-min-spacing", nargs="+", default=["default", "2px"],
                        help="ic's smallest record spacing: what --ic-min-spacing takes (8px, "
                             "5u) or default, the method's (default: %(default)s)")
    parser.add_argument("--rc-rays", nargs="+", type=int, default=[1024, 4096],
                        help="rc's hemisphere rays per radiance record, one curve each, "
                             "--ic-accuracy along it at the first --ic-spp, the diffuse records "
                             "at their defaults (default: %(default)s)")
    parser.add_argument("--sdrc-interp", nargs="+", type=int, default=[1, 4],
                        help="sdrc's lobe directions per camera sample, one curve each, "
                             "--ic-accuracy along it at the first --ic-spp, the diffuse records "
                             "at their defaults (default: %(default)s)")
    parser.add_argument("--ivg-photons", nargs="+", type=int,
                        default=[65536, 262144, 1048576, 4194304],
                        help="ivg's photons along each curve (default: %(default)s)")
    parser.add_argument("--ivg-grid", nargs="+", default=["auto", "auto*2"],
                        help="ivg's grids: auto, auto*K (K times auto's voxels per axis) or "
                             "NxMxK (default: %(default)s)")
    parser.add_argument("--ivg-spp", type=int, default=4,
                        help="ivg's camera samples per pixel (default: %(default)s)")
    parser.add_argument("--gather-rays", nargs="+", type=int, default=[4, 16, 36],
                        help="ivg-gather's rays per camera sample (default: %(default)s)")
    parser.add_argument("--gather-spp", type=int, default=4,
                        help="ivg-gather's camera samples per pixel (default: %(default)s)")
    parser.add_argument("--decomp-alpha", nargs="+", default=["1%"],
                        help="decomposition's alpha, one curve each: what --alpha takes (1%%, "
                             "0.2) (default: %(default)s)")
    parser.add_argument("--decomp-cluster", nargs="+", default=["20%", "10%", "5%", "2%"],
                        help="decomposition's smallest cluster along each curve: what "
                             "--decomp-cluster takes (default: %(default)s)")
    parser.add_argument("--decomp-rays", nargs="+", type=int, default=[512],
                        help="decomposition's rays per cluster, one curve each (default: "
                             "%(default)s)")
    parser.add_argument("--decomp-spp", type=int, default=4,
                        help="decomposition's camera samples per pixel (default: %(default)s)")
    parser.add_argument("--width", type=positive_int, help="override the scene's resolution")
    parser.add_argument("--height", type=positive_int)
    parser.add_argument("--povray", nargs="*", metavar="SETTING",
                        help="add the POV-Ray peer (Cornell box only): its settings, default all")
    parser.add_argument("--denoise", action="store_true",
                        help="beside every radcache point, its image through OIDN with its "
                             "albedo and normal layers (tools/denoise.py), the denoise time "
                             "added to the point's")
    parser.add_argument("--mitsuba", nargs="*", type=int, metavar="SPP",
                        help="add the Mitsuba 3 peer's path tracer at these samples per pixel "
                             "(default %s; tools/peers/mitsuba)" % " ".join(
                                 str(s) for s in MITSUBA_SPP))
    parser.add_argument("--crop", type=int, nargs=4, metavar=("X", "Y", "W", "H"),
                        help="equal-time crop (default: the middle half)")
    parser.add_argument("--out", help="output directory (default build/sweep/SCENE)")
    args, args.extra = parse_with_extra(parser, argv)
    if args.methods is None:
        args.methods = [] if args.ladder else DEFAULT_METHODS
    if args.mitsuba is not None and any(v < 1 for v in args.mitsuba):
        parser.error("--mitsuba: samples per pixel must be positive")
    if args.mitsuba == []:
        args.mitsuba = MITSUBA_SPP
    if args.ladder_spp is not None and args.ladder_spp < 1:
        parser.error("--ladder-spp: must be positive, got %d" % args.ladder_spp)
    for name in ("pt_spp", "ic_rays", "ic_spp", "rc_rays", "sdrc_interp", "ivg_photons",
                 "gather_rays", "decomp_rays"):
        if any(v < 1 for v in getattr(args, name)):
            parser.error("--%s: values must be positive" % name.replace("_", "-"))
    if any(not 0.0 < a for a in args.ic_accuracy):
        parser.error("--ic-accuracy: values must be positive")
    for value in args.decomp_alpha + args.decomp_cluster:
        if not LENGTH_FORM.match(value):
            parser.error("--decomp-alpha, --decomp-cluster: expected a length like 1%% or 0.2, "
                         "got '%s'" % value)
    if args.repeats < 1:
        parser.error("--repeats: at least 1, got %d" % args.repeats)
    for grid in args.ivg_grid:
        if not GRID_FORM.match(grid):
            parser.error("--ivg-grid: expected auto, auto*K or NxMxK, got '%s'" % grid)
    for spacing in args.ic_min_spacing:
        if not SPACING_FORM.match(spacing):
            parser.error("--ic-min-spacing: expected default or a length like 8px or 5u, got "
                         "'%s'" % spacing)
    return args


def radcache_tables():
    """radcache's option tables, once, the curated curves checked against them."""
    radcache.require_built("sweep")
    tables = sweep_knobs.read_tables(lambda args: radcache.run(args, "sweep"))
    try:
        check_curated(tables)
    except sweep_knobs.KnobError as e:
        fail(str(e))
    return tables


def check_tools(repeats):
    if not flip_available():
        print("sweep: warning: flip-evaluator is not installed (python3 -m pip install -r "
              "tools/requirements.txt): the flip column stays empty", file=sys.stderr)
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as e:
        fail("%s: install the tools' Python packages: python3 -m pip install -r "
             "tools/requirements.txt" % e)
    if repeats > 1 and not shutil.which("iinfo"):
        fail("iinfo (openimageio-tools, tools/install-deps.sh) is missing: the repeats' "
             "determinism check needs it")


def write_outputs(report, out, crop):
    rows = report["rows"]
    scene_name = report["scene"]
    if sweep_report.draw_chart(rows, "relmse", "%s: image relMSE against time" % scene_name,
                               os.path.join(out, "error-vs-time.png")):
        report["charts"].append("error-vs-time.png")
    if sweep_report.draw_chart(rows, "flip", "%s: image FLIP against time" % scene_name,
                               os.path.join(out, "flip-vs-time.png"), "mean HDR-FLIP"):
        report["charts"].append("flip-vs-time.png")
    indirect = [dict(r, relmse_indirect=r["indirect_relmse"]) for r in rows]
    if sweep_report.draw_chart(indirect, "relmse_indirect",
                               "%s: indirect relMSE against time" % scene_name,
                               os.path.join(out, "indirect-error-vs-time.png")):
        report["charts"].append("indirect-error-vs-time.png")
    with open(os.path.join(out, "sweep.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        for row in rows:
            writer.writerow({c: row[c] for c in COLUMNS})
    with open(os.path.join(out, "sweep.json"), "w") as f:
        json.dump(report, f, indent=2)
    sweep_report.write_html(report, out, crop)


def main(argv):
    args = parse_arguments(argv)
    tables = radcache_tables()
    methods = selected_methods(args.methods, tables)
    ladders = sweep_ladders(args, methods, tables)
    check_tools(args.repeats)
    args.denoise, mitsuba = sweep_peers.check(args.denoise, args.mitsuba is not None)
    scene, reference, frame, animated = scene_paths(args.scene, args.reference, args.frame)
    check_reference_size(reference, args.width, args.height)
    scene_name = os.path.basename(os.path.dirname(scene))
    out = os.path.abspath(args.out or os.path.join(ROOT, "build", "sweep", scene_name))
    options = ["--frames", "%d:%d" % (frame, frame)] if animated else []
    if args.width:
        options += ["--width", str(args.width)]
    if args.height:
        options += ["--height", str(args.height)]
    options += args.extra
    ladder_spp = ["--spp", str(args.ladder_spp)] if args.ladder_spp else []
    try:
        sweep_knobs.check_values(ladders, ladder_spp + options)
    except sweep_knobs.KnobError as e:
        fail(str(e))
    os.makedirs(out, exist_ok=True)

    names = list(collections.OrderedDict.fromkeys(methods + [l.name for l in ladders]))
    auto_cells = warm_up(scene, out, names, tables, options)
    runs = radcache_runs(args, methods, ladders, auto_cells)
    measured, first_stats = run_points(scene, runs, out, options, args.repeats)
    rows = radcache_rows(runs, measured, first_stats, reference, out)
    if args.povray is not None:
        rows += povray_rows(args, scene, reference, out)

    def measure_peer(row, image, name):
        measure(row, image, reference, out, name)
    if mitsuba:
        rows += sweep_peers.mitsuba_rows(scene, args.mitsuba, (args.width, args.height), out,
                                         measure_peer)
    if args.denoise:
        rows += sweep_peers.denoised_rows(rows, out, measure_peer)
    for row in rows:
        row["scene"] = scene_name
        row["frame"] = frame

    report = {
        "scene": scene_name, "frame": frame, "reference": reference,
        "device": rows[0]["device"] if rows else "", "machine": machine(),
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "git": git_revision(), "repeats": args.repeats,
        "command": " ".join(["tools/sweep.py"] + argv),
        "timing": "median over %d repeats of the render phase of radcache --stats (scene "
                  "loading, device start-up and image writing excluded; kernel binaries warm, "
                  "compilation excluded), bars from the fastest to the slowest; +oidn: that "
                  "plus the denoise step (tools/denoise.py: reading, OIDN and writing, its "
                  "device warm), once; POV-Ray: wall clock of the whole process, one run; "
                  "Mitsuba: mi.render alone, one run (wall_seconds: the whole process)"
                  % args.repeats,
        "columns": COLUMNS, "rows": rows, "charts": [], "skipped": sweep_peers.SKIPPED}
    write_outputs(report, out, args.crop)
    print("%-34s %-36s %9s %15s %11s %8s" % ("curve", "setting", "median s", "min-max s",
                                             "relMSE", "FLIP"))
    for r in rows:
        flip = "%8.4f" % r["flip"] if r["flip"] != "" else "%8s" % "-"
        print("%-34s %-36s %9.3f %7.3f-%-7.3f %11.4g %s" % (
            r["curve"], r["setting"], r["render_seconds"], r["render_seconds_min"],
            r["render_seconds_max"], r["relmse"], flip))
    print("written to %s (sweep.csv, sweep.json, index.html)" % out)


if __name__ == "__main__":
    main(sys.argv[1:])
