#!/usr/bin/env python3
"""Measures and fits the model `radcache render --method auto` plans with (docs/auto.md).

  tools/auto_model.py measure [--scenes cornell-box two-rooms glossy-box] [--sizes 64 128]
                              [--spps S ...] [--knobs A:R ...] [--methods ic rc sdrc]
                              [--out build/auto_model]
  tools/auto_model.py repilot [--data build/auto_model/dataset.json]
  tools/auto_model.py fit [--data build/auto_model/dataset.json]
                          [--write host/methods/auto/auto_model.json]

`measure` renders (skipping a run whose stats file OUT already holds), per scene and image width: auto's pilot (`--dry-run`: the path tracer's noise
v_pt, v_dir and the indirect share f), each caching method's cache pilot (the pilot's size, 1/8 of
the rays, one sample) and the same method at the full size over a small grid of accuracies, rays
per record and samples per pixel: its cache rays W and its relMSE against the scene's reference
(net of the reference's noise). Every run lands in OUT/dataset.json.

`repilot` runs auto's pilot again (this build's) for every scene and size of a dataset and
replaces the runs' noise figures (v_pt, v_dir, f) with its own, so that a changed pilot is
refitted without rendering the runs again.

`fit` fits, per caching method, the cost law W = scale W_p (P/P_p)^gamma (R/R_p)^rho
(a_p/a)^alpha s^sigma (least squares in logarithms) and the error law relMSE =
(delta v_dir + phi v_ind)/s + beta a^2 f^2 + kappa v_ind/R (non-negative least squares on relative
residuals, refined to least squares of log(predicted / measured)) and the error law's spread
(exp of the root mean square of log(predicted / measured)), prints each run's
predicted against measured figures, and writes the constants into the model file (its other
sections kept). The C++ build embeds that file. numpy only.
"""

import argparse
import datetime
import itertools
import json
import os
import subprocess
import sys

from radcache_tools import ROOT, references
from radcache_tools.arguments import positive_int
from radcache_tools.error import relmse_of
from radcache_tools.error import relmse as compared_relmse
from radcache_tools.radcache import run
from radcache_tools.references import shipped_scene_json as scene_json

MODEL = os.path.join(ROOT, "host", "methods", "auto", "auto_model.json")
GLOSSY_METHODS = ["ic", "rc", "sdrc"]
KNOBS = [(0.35, 1024), (0.2, 512), (0.5, 256)]  # (accuracy, rays per record)
PILOT_RAYS = 128  # the pilot's: the default 1024 over the model's rays_divisor 8


def frame_stats(path):
    with open(path) as f:
        return json.load(f)


def cache_rays(frame):
    rays = frame.get("record_rays", 0)
    for cache in ("radiance_cache", "sdrc"):
        rays += frame.get(cache, {}).get("record_rays", 0)
    return rays


def run_unless_done(result, args):
    """radcache ARGS unless `result`, the file it writes, exists (from an earlier measurement)."""
    if not os.path.exists(result):
        run(args)


def relmse(image, reference):
    path = image + ".compare.json"
    if os.path.exists(path):  # from an earlier measurement
        with open(path) as f:
            return relmse_of(json.load(f))
    return compared_relmse(image, reference, path)


def has_glossy(scene):
    materials = references.load_scene_json(scene_json(scene)).get("materials", {})
    return any(m.get("type") in ("phong", "ward") for m in materials.values())


def knob(text):
    """An (accuracy, rays per record) pair written A:R."""
    try:
        accuracy, rays = text.split(":")
        pair = (float(accuracy), int(rays))
    except ValueError:
        raise argparse.ArgumentTypeError("%r is not ACCURACY:RAYS (e.g. 0.35:1024)" % text)
    if not (0.0 < pair[0] <= 1.0) or pair[1] < 1:
        raise argparse.ArgumentTypeError("%r: accuracy in (0, 1], rays at least 1" % text)
    return pair


NOISE = ("v_pt", "v_direct", "indirect_fraction")


def auto_pilot(scene, w, h, stats):
    """auto's pilot (a dry run) of SCENE at w x h, unless STATS holds it: its "pilot" figures."""
    run_unless_done(stats, ["render", scene_json(scene), "--method", "auto", "--dry-run",
                            "--time", "1000", "--stats", stats, "--quiet", "--width", str(w),
                            "--height", str(h)])
    return frame_stats(stats)["plan"]["pilot"]


def measure_scene(scene, width, out, rows, args):
    w, h = references.camera_size(scene_json(scene), width)
    size = ["--width", str(w), "--height", str(h)]
    name = "%s-%d" % (scene, w)
    pilot = auto_pilot(scene, w, h, os.path.join(out, name + ".pilot.json"))
    noise = {k: pilot[k] for k in NOISE}
    methods = [m for m in args.methods if m == "ic" or has_glossy(scene)]
    for method in methods:
        cache_pilot = os.path.join(out, "%s-%s.cache-pilot.json" % (name, method))
        run_unless_done(cache_pilot, [
             "render", scene_json(scene), "--method", method, "--spp", "1", "--ic-rays",
             str(PILOT_RAYS), "--width", str(pilot["width"]), "--height", str(pilot["height"]),
             "--aovs", "beauty", "-o", os.path.join(out, "pilot.exr"), "--stats", cache_pilot,
             "--quiet"])
        pilot_frame = frame_stats(cache_pilot)["frames"][0]
        spps = args.spps or ([4, 32] if width >= 128 else [8])
        for (accuracy, rays), spp in itertools.product(args.knobs or KNOBS, spps):
            stem = os.path.join(out, "%s-%s-a%g-r%d-s%d" % (name, method, accuracy, rays, spp))
            run_unless_done(stem + ".json", [
                "render", scene_json(scene), "--method", method, "--spp", str(spp),
                "--accuracy", "%g" % accuracy, "--ic-rays", str(rays), "-o", stem + ".exr",
                "--stats", stem + ".json", "--quiet"] + size)
            stats = frame_stats(stem + ".json")
            frame = stats["frames"][0]
            row = {"scene": scene, "method": method, "width": w, "height": h,
                   "accuracy": accuracy, "rays": rays, "spp": spp,
                   "pilot_width": pilot["width"], "pilot_height": pilot["height"],
                   "pilot_rays": PILOT_RAYS, "pilot_accuracy": 0.35,
                   "pilot_cache_rays": cache_rays(pilot_frame),
                   "cache_rays": cache_rays(frame),
                   "render_seconds": stats["seconds"]["render"],
                   "relmse": relmse(stem + ".exr", references.best_reference_path(
                       os.path.dirname(scene_json(scene))))}
            row.update(noise)
            rows.append(row)
            print("%s %s a=%g R=%d s=%d: W %.3g (pilot %.3g), relMSE %.3e, %.1f s" % (
                scene, method, accuracy, rays, spp, row["cache_rays"], row["pilot_cache_rays"],
                row["relmse"], row["render_seconds"]), flush=True)


def measure(args):
    """Every scene and size not yet in OUT/dataset.json (the file is rewritten after each, so an
    interrupted measurement goes on where it stopped)."""
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "dataset.json")
    rows = []
    if os.path.exists(path):
        with open(path) as f:
            rows = json.load(f)["rows"]
    git = subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty"],
                         capture_output=True, text=True).stdout.strip()
    for scene in args.scenes:
        for width in args.sizes:
            if any(r["scene"] == scene and r["width"] == width for r in rows):
                continue
            measure_scene(scene, width, args.out, rows, args)
            with open(path, "w") as f:
                json.dump({"date": datetime.date.today().isoformat(), "git": git, "rows": rows},
                          f, indent=1)
    print("wrote %s (%d runs)" % (path, len(rows)))


def read_json(path, what):
    """The JSON file at PATH; exits with one line naming it (and WHAT it is) when it cannot be
    read or is not JSON."""
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as error:
        sys.exit("auto_model.py: %s %s: %s" % (what, path, getattr(error, "strerror", None)
                                               or error))


def repilot(args):
    """The dataset's noise figures replaced by this build's pilot, in place."""
    data = read_json(args.data, "dataset (tools/auto_model.py measure writes it)")
    scratch = os.path.join(os.path.dirname(os.path.abspath(args.data)), "repilot")
    os.makedirs(scratch, exist_ok=True)
    pilots = {}
    for r in data["rows"]:
        key = (r["scene"], r["width"], r["height"])
        if key not in pilots:
            stats = os.path.join(scratch, "%s-%dx%d.pilot.json" % key)
            if os.path.exists(stats):
                os.remove(stats)  # this build's pilot, not an earlier one's
            pilots[key] = auto_pilot(r["scene"], r["width"], r["height"], stats)
            print("%s %dx%d: " % key + ", ".join("%s %.4g" % (k, pilots[key][k]) for k in NOISE))
        r.update({k: pilots[key][k] for k in NOISE})
    data["repiloted"] = datetime.date.today().isoformat()
    with open(args.data, "w") as f:
        json.dump(data, f, indent=1)
    print("wrote %s (%d runs, %d pilots)" % (args.data, len(data["rows"]), len(pilots)))


def fit_cost(rows, np):
    """scale, gamma, rho, alpha, sigma by least squares on log(W / W_p)."""
    a = np.array([[1.0,
                   np.log(r["width"] * r["height"] / (r["pilot_width"] * r["pilot_height"])),
                   np.log(r["rays"] / r["pilot_rays"]),
                   np.log(r["pilot_accuracy"] / r["accuracy"]),
                   np.log(r["spp"])] for r in rows])
    y = np.array([np.log(max(r["cache_rays"], 1) / max(r["pilot_cache_rays"], 1)) for r in rows])
    coef = np.linalg.lstsq(a, y, rcond=None)[0]
    return {"scale": float(np.exp(coef[0])), "gamma": max(0.0, float(coef[1])),
            "rho": max(0.0, float(coef[2])), "alpha": max(0.0, float(coef[3])),
            "sigma": max(0.0, float(coef[4]))}


ERROR_CONSTANTS = ["delta", "phi", "beta", "kappa"]


def error_features(r):
    v_ind = max(r["v_pt"] - r["v_direct"], 0.0)
    f = r["indirect_fraction"]
    return [r["v_direct"] / r["spp"], v_ind / r["spp"], r["accuracy"] ** 2 * f * f,
            v_ind / r["rays"]]


def fit_error(rows, np):
    """delta, phi, beta, kappa >= 0 minimising the relative residuals (every active set tried)."""
    x = np.array([error_features(r) for r in rows])
    y = np.array([max(r["relmse"], 1e-12) for r in rows])
    weight = 1.0 / y
    best = None
    n = len(ERROR_CONSTANTS)
    for active in itertools.product([False, True], repeat=n):
        cols = [i for i in range(n) if active[i]]
        coef = np.zeros(n)
        if cols:
            sol = np.linalg.lstsq(x[:, cols] * weight[:, None], y * weight, rcond=None)[0]
            if (sol < 0).any():
                continue
            coef[cols] = sol
        residual = float(np.sum(((x @ coef - y) * weight) ** 2))
        if best is None or residual < best[0]:
            best = (residual, coef)
    coef = refine_in_logarithms(x, y, best[1], np)
    return {name: float(c) for name, c in zip(ERROR_CONSTANTS, coef)}


def refine_in_logarithms(x, y, start, np, steps=300):
    """The constants minimising sum log(predicted / measured)^2 (over- and under-prediction by
    the same factor weigh the same), by Levenberg-Marquardt on their logarithms from `start`
    (a constant at 0 starts at 1e-9 of the largest feature's scale)."""
    floor = 1e-9 * np.maximum(y.max() / np.maximum(x.max(axis=0), 1e-300), 1e-300)
    theta = np.log(np.maximum(start, floor))
    damping = 1e-3

    def residuals(t):
        return np.log(x @ np.exp(t)) - np.log(y)

    r = residuals(theta)
    for _ in range(steps):
        c = np.exp(theta)
        jacobian = (x * c) / (x @ c)[:, None]
        normal = jacobian.T @ jacobian
        step = np.linalg.solve(normal + damping * np.diag(np.diag(normal) + 1e-12),
                               -jacobian.T @ r)
        trial = residuals(theta + step)
        if trial @ trial < r @ r:
            theta, r, damping = theta + step, trial, damping * 0.5
        else:
            damping *= 4.0
    return np.exp(theta)


def predicted_error(r, e):
    return sum(e[name] * x for name, x in zip(ERROR_CONSTANTS, error_features(r)))


def error_spread(rows, e, np):
    """The law's typical factor of error on `rows`: exp of the root mean square of
    log(predicted / measured), at least 1 (auto keeps a method's default knobs unless others are
    predicted better by more than this)."""
    logs = [np.log(max(predicted_error(r, e), 1e-300) / max(r["relmse"], 1e-300)) for r in rows]
    return max(1.0, float(np.exp(np.sqrt(np.mean(np.square(logs)))))) if logs else 1.0


def predicted_cost(r, c):
    return (c["scale"] * r["pilot_cache_rays"] *
            (r["width"] * r["height"] / (r["pilot_width"] * r["pilot_height"])) ** c["gamma"] *
            (r["rays"] / r["pilot_rays"]) ** c["rho"] *
            (r["pilot_accuracy"] / r["accuracy"]) ** c["alpha"] * r["spp"] ** c["sigma"])


def fit(args):
    import numpy as np
    data = read_json(args.data, "dataset (tools/auto_model.py measure writes it)")
    model = read_json(args.write, "model file")
    print("| scene | method | size | a | R | spp | W / predicted | relMSE | predicted |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    glossy = {scene: has_glossy(scene) for scene in {r["scene"] for r in data["rows"]}}
    for method in sorted({r["method"] for r in data["rows"]}):
        # ic renders under auto only where no glossy lobe is cached: its constants come from the
        # scenes without glossy lobes (on the others it path-traces them, another regime).
        rows = [r for r in data["rows"] if r["method"] == method and
                not (method == "ic" and glossy[r["scene"]] and
                     any(not glossy[q["scene"]] for q in data["rows"] if q["method"] == "ic"))]
        model["cost"][method] = {k: round(v, 4) for k, v in fit_cost(rows, np).items()}
        wide = [r for r in rows if r["width"] >= args.error_min_width] or rows
        model["error"][method] = {k: float("%.4g" % v) for k, v in fit_error(wide, np).items()}
        model["error"][method]["spread"] = float("%.4g" % error_spread(wide, model["error"][method],
                                                                       np))
        for r in rows:
            print("| %s | %s | %dx%d | %g | %d | %d | %.2f | %.2e | %.2e |" % (
                r["scene"], method, r["width"], r["height"], r["accuracy"], r["rays"], r["spp"],
                r["cache_rays"] / predicted_cost(r, model["cost"][method]), r["relmse"],
                predicted_error(r, model["error"][method])))
    model["fitted"] = ("tools/auto_model.py fit, %s, from %d runs measured %s at git %s (%s)" % (
        datetime.date.today().isoformat(), len(data["rows"]), data["date"], data["git"],
        ", ".join(sorted({r["scene"] for r in data["rows"]}))))
    with open(args.write, "w") as f:
        f.write(json.dumps(model, indent=4) + "\n")
    print("wrote %s" % args.write)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    m = sub.add_parser("measure", help="render the runs the fit reads")
    m.add_argument("--scenes", nargs="+", default=["cornell-box", "two-rooms", "glossy-box"])
    m.add_argument("--sizes", nargs="+", type=positive_int, default=[64, 128])
    m.add_argument("--spps", nargs="+", type=positive_int,
                   help="samples per pixel of each run (default: 4 and 32 at 128 wide and more, "
                        "8 below)")
    m.add_argument("--knobs", nargs="+", type=knob,
                   help="(accuracy, rays per record) pairs A:R (default: %s)" %
                        " ".join("%g:%d" % k for k in KNOBS))
    m.add_argument("--methods", nargs="+", choices=GLOSSY_METHODS, default=GLOSSY_METHODS,
                   help="caching methods to measure (ic on every scene, rc and sdrc on scenes "
                        "with glossy materials)")
    m.add_argument("--out", default=os.path.join(ROOT, "build", "auto_model"))
    p = sub.add_parser("repilot", help="replace the dataset's noise figures with this build's "
                                       "pilot")
    p.add_argument("--data", default=os.path.join(ROOT, "build", "auto_model", "dataset.json"))
    f = sub.add_parser("fit", help="fit the constants and write the model file")
    f.add_argument("--data", default=os.path.join(ROOT, "build", "auto_model", "dataset.json"))
    f.add_argument("--write", default=MODEL)
    f.add_argument("--error-min-width", type=positive_int, default=128,
                   help="fit the error law to runs at least this wide only (default %(default)s: "
                        "at fewer pixels the light's edges at a few samples dominate the error, "
                        "which the law does not model); the cost law is fitted to every run")
    args = parser.parse_args()
    {"measure": measure, "repilot": repilot, "fit": fit}[args.command](args)


if __name__ == "__main__":
    main()
