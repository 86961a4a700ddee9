#!/usr/bin/env python3
"""Tabulates how a collection of public scene files fares: each pbrt-v4 (.pbrt with WorldBegin)
or glTF (.gltf, .glb) file under FOLDER rendered at a tiny size with each --method: rendered,
refused (exit status 2: a feature radcache does not have, the line naming it) or failed (any
other status, or past --timeout).

Public snapshots (the search tool's fetch) leave out files of 4 MiB or more, so the renders run
in a copy of FOLDER (hard links) where each file a render reports as not found (an image
texture, a PLY mesh, an included pbrt file) is stood in for by a neutral one: a 2 x 2 grey image
(through oiiotool), a PLY of one small triangle (gzipped for .ply.gz), an empty pbrt file; the
table counts the stand-ins each scene needed.
FOLDER itself is not written.

Usage: tools/bench/collection.py FOLDER [--methods pt auto] [--out build/bench/collection]
           [--radcache build/radcache] [--timeout 300] [--size 8] [--spp 1] [-- extra options]
Writes OUT/collection.json (every run) and OUT/collection.md (the table and the counts), and
prints the counts.
"""

import argparse
import gzip
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import time

from radcache_tools import ROOT
from radcache_tools import radcache
from radcache_tools.arguments import parse_with_extra, positive_int, positive_seconds

# What a render says of a file it lacks (host/scene/texture.cpp, pbrt_shapes.cpp, gltf_loader).
MISSING = [re.compile(r'image file "([^"]+)" not found'),
           re.compile(r": ([^:]+\.ply(?:\.gz)?): PLY file not found"),
           re.compile(r"Include ([^:]+\.pbrt): file not found")]
# The most stand-ins one scene may get before it counts as failed.
MAX_STAND_INS = 200
PLY_STAND_IN = ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "end_header\n0 0 0\n0.001 0 0\n0 0.001 0\n3 0 1 2\n")


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("folder")
    parser.add_argument("--methods", nargs="+", default=["pt", "auto"])
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "collection"))
    parser.add_argument("--radcache", default=radcache.executable(),
                        help="the radcache to run (default: $RADCACHE, else build/radcache)")
    parser.add_argument("--timeout", type=positive_seconds, default=300.0)
    parser.add_argument("--size", type=positive_int, default=8)
    parser.add_argument("--spp", type=positive_int, default=1)
    arguments, arguments.extra = parse_with_extra(parser, argv)
    return arguments


def scene_files(folder):
    """Every scene file under folder, relative to it, sorted: pbrt files that hold WorldBegin
    (not the files they include) and glTF files."""
    found = []
    for directory, _, names in os.walk(folder):
        for name in names:
            path = os.path.join(directory, name)
            if name.endswith((".gltf", ".glb")):
                found.append(path)
            elif name.endswith(".pbrt"):
                with open(path, "rb") as f:
                    if b"WorldBegin" in f.read():
                        found.append(path)
    return sorted(os.path.relpath(p, folder) for p in found)


def stand_in(path):
    """Writes a neutral file at path for a missing texture or mesh; its kind."""
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    if path.endswith(".ply"):
        with open(path, "w") as f:
            f.write(PLY_STAND_IN)
        return "mesh"
    if path.endswith(".pbrt"):
        open(path, "w").close()
        return "include"
    if path.endswith(".ply.gz"):
        with gzip.open(path, "wt") as f:
            f.write(PLY_STAND_IN)
        return "mesh"
    if path.lower().endswith(".pfm"):
        # OpenImageIO reads PFM but does not write it: 2 x 2 RGB floats, little-endian.
        with open(path, "wb") as f:
            f.write(b"PF\n2 2\n-1.0\n" + struct.pack("<12f", *([0.5] * 12)))
        return "image"
    subprocess.run(["oiiotool", "--pattern", "constant:color=0.5,0.5,0.5", "2x2", "3", "-o", path],
                   check=True, capture_output=True)
    return "image"


def first_error(output):
    for line in output.splitlines():
        if "error:" in line:
            return line.strip()
    lines = [l for l in output.splitlines() if "warning" not in l]
    return lines[-1].strip() if lines else ""


def render(arguments, work, scene, method):
    """One scene with one method, standing in for what it lacks; the run's record."""
    command = [arguments.radcache, "render", scene, "-o", os.path.join(arguments.out, "scan.png"),
               "--method", method, "--width", str(arguments.size), "--height",
               str(arguments.size), "--spp", str(arguments.spp), "-q"] + arguments.extra
    stand_ins = []
    while True:
        start = time.monotonic()
        try:
            result = subprocess.run(command, cwd=work, capture_output=True, text=True,
                                    timeout=arguments.timeout)
            code, output = result.returncode, result.stdout + result.stderr
        except subprocess.TimeoutExpired:
            code, output = None, "past the %g s timeout" % arguments.timeout
        seconds = time.monotonic() - start
        missing = next((m.group(1) for pattern in MISSING for m in [pattern.search(output)] if m),
                       None)
        if code == 1 and missing and len(stand_ins) < MAX_STAND_INS and \
                not os.path.exists(os.path.join(work, missing)):
            stand_ins.append("%s (%s)" % (missing, stand_in(os.path.join(work, missing))))
            continue
        outcome = "rendered" if code == 0 else "refused" if code == 2 else "failed"
        return {"scene": scene, "method": method, "outcome": outcome, "exit_status": code,
                "seconds": round(seconds, 2), "message": "" if code == 0 else first_error(output),
                "stand_ins": stand_ins}


def table(runs, methods):
    lines = ["| scene | " + " | ".join(methods) + " | stand-ins | first refusal or failure |",
             "| --- | " + " | ".join("---" for _ in methods) + " | ---: | --- |"]
    by_scene = {}
    for run in runs:
        by_scene.setdefault(run["scene"], {})[run["method"]] = run
    for scene, row in by_scene.items():
        message = next((r["message"] for r in row.values() if r["message"]), "")
        stand_ins = max(len(r["stand_ins"]) for r in row.values())
        lines.append("| %s | %s | %d | %s |" % (
            scene, " | ".join(row[m]["outcome"] for m in methods), stand_ins,
            message.replace("|", "\\|")[:200]))
    counts = []
    for method in methods:
        outcomes = [r["outcome"] for r in runs if r["method"] == method]
        counts.append("%s: %d of %d rendered, %d refused, %d failed" % (
            method, outcomes.count("rendered"), len(outcomes), outcomes.count("refused"),
            outcomes.count("failed")))
    return "\n".join(lines), counts


def main(argv):
    arguments = parse_arguments(argv)
    arguments.radcache = os.path.abspath(arguments.radcache)
    arguments.out = os.path.abspath(arguments.out)
    folder = os.path.abspath(arguments.folder)
    if not os.path.isdir(folder):
        print("collection: %s is not a folder" % arguments.folder, file=sys.stderr)
        return 2
    work = os.path.join(arguments.out, "work")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(arguments.out, exist_ok=True)
    shutil.copytree(folder, work, copy_function=os.link, symlinks=True)
    runs = []
    for scene in scene_files(work):
        for method in arguments.methods:
            runs.append(render(arguments, work, scene, method))
            print("%s %s: %s %s" % (scene, method, runs[-1]["outcome"], runs[-1]["message"][:120]),
                  flush=True)
    markdown, counts = table(runs, arguments.methods)
    with open(os.path.join(arguments.out, "collection.json"), "w") as f:
        json.dump({"folder": arguments.folder, "runs": runs}, f, indent=1)
    with open(os.path.join(arguments.out, "collection.md"), "w") as f:
        f.write(markdown + "\n\n" + "\n".join("- " + c for c in counts) + "\n")
    print("\n".join(counts))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
