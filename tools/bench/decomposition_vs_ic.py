#!/usr/bin/env python3
"""Irradiance decomposition against irradiance caching at equal error (its time and ray targets).

The paper (Arikan et al. 2005, §8): "an order of magnitude faster than irradiance caching ...
while providing the same quality images", with far fewer rays. Ours: on the detail scene
(scenes/relief) `decomposition` reaches `ic`'s relMSE in at most 1/5 of its time and with at
most 1/10 of its rays.

For each scene, at --spp camera samples per pixel (default 4, the sweep's for the caching
methods): renders `--method ic` at its defaults (the irradiance cache the targets name; and
`ic --ic-ivg`, irradiance caching over the same grid the decomposition reads, with
--with-ic-ivg), then `--method decomposition` at its defaults and over a ladder of settings
(--source x --rays x --alpha x --cluster x --visibility x --radiosity x --gradients x --near x
--indirect-spp: --decomp-source, --decomp-rays, --alpha, --decomp-cluster, --decomp-visibility,
--decomp-radiosity, --decomp-gradients, --decomp-near, --decomp-indirect-spp; `--near default`
leaves the near set to follow the radiosity, `--indirect-spp 0` the evaluation at --spp), each
point --repeats times in rounds (median render time).
Every image is measured against the scene's reference: relMSE of the beauty and of the indirect
layer (`radcache compare`). For each ic run it names the fastest decomposition setting whose
relMSE (of the layer --layer, default indirect) is at most ic's, and the ratios of render time
and of rays (all rays the frame traced: camera, shadow, gather and photon rays; and the indirect
rays alone: ic's record rays against the decomposition's cluster, radiosity and photon rays).
All runs happen side by side in this one invocation, on the same device, kernel binaries warm
(one untimed render of each method first). Times are the render phase of `--stats` (scene
loading, device start and image writing excluded).

Usage: tools/bench/decomposition_vs_ic.py [--scenes relief] [--spp 4] [--source grid path]
           [--alpha 1%] [--cluster 10% 5% 2%] [--rays 512 2048] [--visibility heuristic]
           [--radiosity gathered] [--gradients on] [--near default] [--indirect-spp 0]
           [--repeats 2]
           [--with-ic-ivg]
           [--layer indirect]
           [--out build/bench/decomposition]
           [-- extra render options]
Writes OUT/decomposition_vs_ic.json (every run) and OUT/decomposition_vs_ic.md (the tables),
and prints the tables. Python 3 standard library only.
"""

import argparse
import itertools
import json
import os
import statistics
import sys

from radcache_tools import ROOT
from radcache_tools import references
from radcache_tools.arguments import parse_with_extra
from radcache_tools import radcache
from radcache_tools.error import relmse
from radcache_tools.radcache import render


def indirect_rays(method, frame):
    """The rays a frame traced for indirect light: ic's record rays (its hemisphere rays and
    their paths, or the grid's photons and lookups); the decomposition's cluster and radiosity
    rays; each plus the grid's photon rays where it built one."""
    photons = frame.get("grid", {}).get("photon_rays", 0)
    if method == "decomposition":
        return frame["cluster_rays_traced"] + frame["radiosity_rays"] + photons
    return frame["record_rays"] + photons


def runs_of(args):
    """(name, method, setting, options) of every timed run of a scene."""
    spp = ["--spp", str(args.spp)]
    runs = [("ic", "ic", "defaults", ["--method", "ic"] + spp)]
    if args.with_ic_ivg:
        runs.append(("ic-ivg", "ic", "--ic-ivg", ["--method", "ic", "--ic-ivg"] + spp))
    runs.append(("decomposition", "decomposition", "defaults",
                 ["--method", "decomposition"] + spp))
    for (source, rays, alpha, size, visibility, radiosity, gradients, near,
         indirect_spp) in itertools.product(
            args.source, args.rays, args.alpha, args.cluster, args.visibility, args.radiosity,
            args.gradients, args.near, args.indirect_spp):
        setting = "%s, alpha %s, cluster %s, %d rays, %s, %s radiosity, gradients %s" % (
            source, alpha, size, rays, visibility, radiosity, gradients)
        more = []
        if near != "default":
            setting += ", near set " + near
            more += ["--decomp-near", near]
        if indirect_spp > 0:
            setting += ", indirect spp %d" % indirect_spp
            more += ["--decomp-indirect-spp", str(indirect_spp)]
        runs.append(("decomposition", "decomposition", setting,
                     ["--method", "decomposition", "--decomp-source", source, "--alpha", alpha,
                      "--decomp-cluster", size, "--decomp-rays", str(rays),
                      "--decomp-visibility", visibility, "--decomp-radiosity", radiosity,
                      "--decomp-gradients", gradients] + more
                     + spp))
    return runs


def measure_scene(name, args, extra):
    scene = os.path.join(ROOT, "scenes", name, "scene.json")
    reference = references.reference_path(os.path.dirname(scene), None)
    out = os.path.join(args.out, name)
    os.makedirs(out, exist_ok=True)
    for method in ("ic", "decomposition"):
        render(scene, os.path.join(out, "warm-%s.exr" % method),
               ["--method", method, "--spp", "1"] + extra)
    runs = runs_of(args)
    seconds = [[] for _ in runs]
    first = [None] * len(runs)
    for repeat in range(args.repeats):
        for i, (label, method, setting, options) in enumerate(runs):
            print("[%s, repeat %d/%d] %s %s" % (name, repeat + 1, args.repeats, label, setting),
                  flush=True)
            image = os.path.join(out, "%02d-%s.exr" % (i, label))
            stats = render(scene, image, options + extra)
            seconds[i].append(stats["seconds"]["render"])
            if repeat == 0:
                first[i] = stats
    rows = []
    for i, (label, method, setting, options) in enumerate(runs):
        image = os.path.join(out, "%02d-%s.exr" % (i, label))
        frame = first[i]["frames"][0]
        rows.append({
            "scene": name, "run": label, "setting": setting, "options": options + extra,
            "seconds": statistics.median(seconds[i]), "seconds_all": seconds[i],
            "rays": first[i]["rays"], "indirect_rays": indirect_rays(method, frame),
            "records": frame.get("records", ""),
            "relmse": relmse(image, reference, image + ".beauty.json", "beauty",
                             ["--error-image", image + ".error.png"]),
            "indirect_relmse": relmse(image, reference, image + ".indirect.json", "indirect",
                                      ["--error-image", image + ".indirect-error.png"]),
            "device": first[i]["device"]})
    return rows


def comparisons(rows, layer):
    """For each ic run: the fastest decomposition run of the same scene at most as far from
    the reference."""
    key = "indirect_relmse" if layer == "indirect" else "relmse"
    lines = []
    for base in [r for r in rows if r["run"] != "decomposition"]:
        reaching = [r for r in rows if r["run"] == "decomposition"
                    and r["scene"] == base["scene"] and r[key] <= base[key]]
        if not reaching:
            lines.append({"scene": base["scene"], "against": base["run"], "layer": layer,
                          "target": base[key], "reached": False})
            continue
        best = min(reaching, key=lambda r: r["seconds"])
        lines.append({"scene": base["scene"], "against": base["run"], "layer": layer,
                      "target": base[key], "reached": True, "setting": best["setting"],
                      "relmse": best[key], "time_ratio": best["seconds"] / base["seconds"],
                      "ray_ratio": best["rays"] / base["rays"],
                      "indirect_ray_ratio": best["indirect_rays"] / base["indirect_rays"]})
    return lines


def tables(rows, lines):
    text = ["| scene | run | setting | render s | rays | indirect rays | records / SH samples "
            "| relMSE | indirect relMSE |", "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: "
            "| ---: |"]
    for r in rows:
        text.append("| %s | %s | %s | %.2f | %.3g | %.3g | %s | %.3g | %.3g |" % (
            r["scene"], r["run"], r["setting"], r["seconds"], r["rays"], r["indirect_rays"],
            r["records"], r["relmse"], r["indirect_relmse"]))
    text += ["", "| scene | against | layer | its relMSE | decomposition reaching it | relMSE "
             "| time ratio | ray ratio | indirect-ray ratio |",
             "| --- | --- | --- | ---: | --- | ---: | ---: | ---: | ---: |"]
    for c in lines:
        if c["reached"]:
            text.append("| %s | %s | %s | %.3g | %s | %.3g | %.3f | %.3f | %.3f |" % (
                c["scene"], c["against"], c["layer"], c["target"], c["setting"], c["relmse"],
                c["time_ratio"], c["ray_ratio"], c["indirect_ray_ratio"]))
        else:
            text.append("| %s | %s | %s | %.3g | none of the settings | | | | |" % (
                c["scene"], c["against"], c["layer"], c["target"]))
    return "\n".join(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", nargs="+", default=["relief"])
    parser.add_argument("--source", nargs="+", choices=["grid", "path", "radiosity"],
                        default=["grid", "path"])
    parser.add_argument("--alpha", nargs="+", default=["1%"])
    parser.add_argument("--cluster", nargs="+", default=["10%", "5%", "2%"])
    parser.add_argument("--rays", nargs="+", type=int, default=[512, 2048])
    parser.add_argument("--visibility", nargs="+", choices=["heuristic", "rays"],
                        default=["heuristic"])
    parser.add_argument("--radiosity", nargs="+", choices=["gathered", "coarse"],
                        default=["gathered"],
                        help="the near triangles' radiosity (--decomp-radiosity; default "
                             "%(default)s)")
    parser.add_argument("--gradients", nargs="+", choices=["off", "on"], default=["on"],
                        help="the far field's translational gradients (--decomp-gradients; "
                             "default %(default)s)")
    parser.add_argument("--near", nargs="+", choices=["default", "touching", "centroid"],
                        default=["default"],
                        help="eq. 4's near set (--decomp-near; default: not given, so it follows "
                             "the radiosity)")
    parser.add_argument("--indirect-spp", nargs="+", type=int, default=[0],
                        help="camera samples per pixel of the two terms (--decomp-indirect-spp; "
                             "default 0: not given, so --spp)")
    parser.add_argument("--spp", type=int, default=4,
                        help="camera samples per pixel of every run (default %(default)s)")
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--with-ic-ivg", action="store_true",
                        help="also irradiance caching over the grid (ic --ic-ivg)")
    parser.add_argument("--layer", choices=["indirect", "beauty"], default="indirect",
                        help="the layer whose relMSE decides equal error (default indirect: "
                             "the beauty's is mostly the direct light's noise, the same in both)")
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "decomposition"))
    args, extra = parse_with_extra(parser, sys.argv[1:])
    radcache.require_built()
    if args.repeats < 1 or args.spp < 1:
        sys.exit("--repeats and --spp must be at least 1")
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for name in args.scenes:
        rows += measure_scene(name, args, extra)
    lines = comparisons(rows, args.layer)
    text = tables(rows, lines)
    with open(os.path.join(args.out, "decomposition_vs_ic.json"), "w") as f:
        json.dump({"command": " ".join(["tools/bench/decomposition_vs_ic.py"] + sys.argv[1:]),
                   "rows": rows, "comparisons": lines}, f, indent=2)
    with open(os.path.join(args.out, "decomposition_vs_ic.md"), "w") as f:
        f.write(text + "\n")
    print(text)


if __name__ == "__main__":
    main()
