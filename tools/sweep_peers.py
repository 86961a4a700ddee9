"""tools/sweep.py's curves of what a user would pick instead of radcache's methods (a library,
not a command): every radcache point passed through OIDN (--denoise: tools/denoise.py) and the
Mitsuba 3 peer's path tracer (--mitsuba: tools/peers/mitsuba/ladder.py). Both are optional: without
their packages the sweep skips their curves with one warning each."""

import csv
import os
import shutil
import subprocess
import sys
import time

import denoise

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
LADDER = os.path.join(ROOT, "tools", "peers", "mitsuba", "ladder.py")
DENOISED = "+oidn"
# A peer row's columns that no radcache knob or stat fills.
EMPTY = ["spp", "accuracy", "ic_rays", "ic_min_spacing", "rc_rays", "sdrc_interp", "photons",
         "grid", "gather_rays", "kernel_seconds", "kernel_seconds_min", "kernel_seconds_max",
         "compile_seconds", "records", "denoise_seconds"]


# The warnings of skipped curves, for the sweep's report (tools/results.py quotes them).
SKIPPED = []


def warn(message):
    SKIPPED.append(message)
    print("sweep: warning: " + message, file=sys.stderr)


def mitsuba_available():
    try:
        import mitsuba  # noqa: F401
    except ImportError:
        return False
    return True


def check(want_denoise, want_mitsuba):
    """(denoise, mitsuba) as they can run: a requested one whose packages are missing is
    dropped with one warning."""
    if want_denoise and not denoise.available():
        warn("pyoidn or OpenEXR is not installed (tools/install-deps.sh): no +oidn curves")
        want_denoise = False
    if want_mitsuba and not mitsuba_available():
        warn("mitsuba is not installed (tools/install-deps.sh): no Mitsuba curve")
        want_mitsuba = False
    return want_denoise, want_mitsuba


def denoised_row(row, out, measure):
    """The row of one radcache point's image through OIDN: its times plus the denoise step's
    (reading, filtering and writing the EXR, the OIDN device already warm)."""
    source = os.path.join(out, row["image"])
    name = os.path.splitext(row["image"])[0] + ".oidn"
    target = os.path.join(out, name + ".exr")
    start = time.perf_counter()
    denoise.denoise_file(source, target)
    seconds = time.perf_counter() - start
    new = dict(row, method=row["method"] + DENOISED, curve=row["curve"] + " " + DENOISED,
               denoise_seconds=seconds)
    for key in ("wall_seconds", "render_seconds"):
        for suffix in ("", "_min", "_max"):
            new[key + suffix] = row[key + suffix] + seconds
    measure(new, target, name)
    new["indirect_relmse"] = ""  # only the beauty is denoised
    return new


def denoised_rows(rows, out, measure):
    """A +oidn row beside every radcache row whose image has the auxiliary layers."""
    denoisable = [r for r in rows if r["method"] not in ("povray", "mitsuba")]
    if not denoisable:
        return []
    warm = os.path.join(out, "warm-oidn.exr")
    try:
        denoise.denoise_file(os.path.join(out, denoisable[0]["image"]), warm)
    except denoise.DenoiseError as e:
        warn("no +oidn curves: %s" % e)
        return []
    os.remove(warm)
    return [denoised_row(r, out, measure) for r in denoisable]


def mitsuba_rows(scene, spp, size, out, measure):
    """The Mitsuba peer's ladder on the scene, one row per spp; none (one warning) when the
    exporter refuses the scene."""
    peer_out = os.path.join(out, "mitsuba")
    command = [sys.executable, LADDER, scene, "--out", peer_out, "--spp"] + [str(s) for s in spp]
    for name, value in zip(("--width", "--height"), size):
        if value:
            command += [name, str(value)]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        warn("no Mitsuba curve: %s" % (result.stderr.strip().splitlines() or ["failed"])[-1])
        return []
    rows = []
    with open(os.path.join(peer_out, "mitsuba.csv")) as f:
        for peer in csv.DictReader(f):
            name = "mitsuba-" + peer["setting"].replace("=", "")
            row = {key: "" for key in EMPTY}
            row.update({"method": "mitsuba", "curve": "Mitsuba %s path" % peer["mitsuba"],
                        "setting": peer["setting"], "spp": int(peer["spp"]), "repeats": 1,
                        "device": "Mitsuba %s %s, %s threads" % (
                            peer["mitsuba"], peer["variant"], peer["threads"])})
            for key in ("wall_seconds", "render_seconds"):
                row[key] = row[key + "_min"] = row[key + "_max"] = float(peer[key])
            image = os.path.join(out, name + ".exr")
            shutil.copyfile(peer["image"], image)
            measure(row, image, name)
            rows.append(row)
    return rows
