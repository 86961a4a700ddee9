#!/usr/bin/env python3
"""Renders a scene on a Slurm cluster: frames, tiles (--crop) and sample ranges (--sample-range)
as the tasks of a job array, and their merge (radcache merge) after it (docs/farm.md).

    tools/farm.py SCENE --out DIR [--frames A:B] [--frames-per-task N] [--tiles CxR]
                  [--sample-ranges K] [--spp N] [--gpu] [--cache-prepass]
                  [--radcache PATH | --bundle DIR] [--dry-run] -- [radcache render options]

DIR receives the batch scripts (scripts/), the tasks' logs (logs/), their parts (parts/), a mark
for each task that finished (done/) and the frames (frame.####.exr, merged). Run again with the
same arguments after a failure, it submits only the tasks without a mark, then the merge.
radcache grows no network protocol: Slurm runs the tasks, the files carry the results.
"""

import argparse
import os
import shlex
import shutil
import subprocess
import sys
import time
from pathlib import Path

RENDER_ARRAY = "render.sbatch"
MERGE = "merge.sbatch"
PREPASS = "prepass.sbatch"


# Slurm's largest array: MaxArraySize is at most 4 000 001, the indices 0 .. 4 000 000.
MAX_ARRAY_TASKS = 4_000_001


def fail(message, status=1):
    print(f"farm: {message}", file=sys.stderr)
    sys.exit(status)


def parse_range(text, option):
    try:
        first, last = (int(word) for word in text.split(":"))
    except ValueError:
        fail(f"{option}: expected A:B, got '{text}'", 2)
    if last < first:
        fail(f"{option} {text}: ends before it starts", 2)
    return first, last


def parse_tiles(text):
    try:
        columns, rows = (int(word) for word in text.lower().split("x"))
    except ValueError:
        fail(f"--tiles: expected CxR (columns x rows), got '{text}'", 2)
    if columns < 1 or rows < 1:
        fail(f"--tiles {text}: at least 1x1", 2)
    return columns, rows


def arguments(argv):
    parser = argparse.ArgumentParser(
        prog="tools/farm.py", description=__doc__.split("\n\n")[0],
        epilog="Options after -- are radcache render's, given to every task.")
    parser.add_argument("scene", type=Path)
    parser.add_argument("--out", type=Path, required=True, help="the farm's folder")
    parser.add_argument("--frames", default="0:0", help="frames A:B (default 0:0)")
    parser.add_argument("--frames-per-task", type=int, default=1, metavar="N")
    parser.add_argument("--tiles", default="1x1", metavar="CxR",
                        help="split each frame into C columns and R rows of --crop windows")
    parser.add_argument("--sample-ranges", type=int, default=1, metavar="K",
                        help="split each pixel's --spp samples into K ranges (pt)")
    parser.add_argument("--pre-roll", type=int, default=0, metavar="K",
                        help="with --temporal after --: each task first renders the K frames "
                             "before its own (from the clip's first at most) without writing "
                             "them (radcache render --write-from), so its records are warm; K at "
                             "least the clip's length gives every frame as one process renders "
                             "it (default 0)")
    parser.add_argument("--spp", type=int, default=16, help="samples per pixel (default 16)")
    parser.add_argument("--width", type=int, required=True)
    parser.add_argument("--height", type=int, required=True)
    parser.add_argument("--gpu", action="store_true", help="ask one GPU per task (--gres=gpu:1)")
    parser.add_argument("--cache-prepass", action="store_true",
                        help="caching methods (ic, rc, sdrc), one frame: a job before the array "
                             "renders the frame with --cache-out DIR/cache.rcc, every task reads "
                             "it with --cache-in (tiles then show no seams)")
    parser.add_argument("--partition", help="the Slurm partition (default: the cluster's)")
    parser.add_argument("--radcache", default=os.environ.get("RADCACHE", "radcache"),
                        help="the radcache the nodes run (default $RADCACHE, else on the PATH)")
    parser.add_argument("--bundle", type=Path,
                        help="an unpacked tools/bundle.sh bundle the nodes run (its ./radcache)")
    parser.add_argument("--dry-run", action="store_true", help="print the scripts, submit nothing")
    parser.add_argument("--poll", type=float, default=2.0, help="seconds between looks at squeue")
    cut = argv.index("--") if "--" in argv else len(argv)
    options = parser.parse_args(argv[:cut])
    options.render = argv[cut + 1:]
    if options.frames_per_task < 1 or options.sample_ranges < 1 or options.spp < 1:
        fail("--frames-per-task, --sample-ranges and --spp must be at least 1", 2)
    if options.pre_roll < 0:
        fail(f"--pre-roll {options.pre_roll}: must be at least 0", 2)
    if options.width < 1 or options.height < 1:
        fail(f"--width {options.width} --height {options.height}: must be at least 1", 2)
    if not options.poll > 0:
        fail(f"--poll {options.poll}: must be a positive number of seconds", 2)
    # The tasks counted before any is built: a Slurm array holds at most MAX_ARRAY_TASKS.
    first, last = parse_range(options.frames, "--frames")
    columns, rows = parse_tiles(options.tiles)
    count = (-(-(last - first + 1) // options.frames_per_task) * columns * rows
             * options.sample_ranges)
    if count > MAX_ARRAY_TASKS:
        fail(f"--frames {options.frames}: {count} tasks, more than a Slurm array holds "
             f"({MAX_ARRAY_TASKS}): raise --frames-per-task", 2)
    if options.sample_ranges > options.spp:
        fail(f"--sample-ranges {options.sample_ranges}: more ranges than --spp {options.spp}", 2)
    for refused in ("-o", "--output", "--frames", "--crop", "--sample-range", "--spp",
                    "--width", "--height", "--write-sums", "--write-from", "--clip-end"):
        if refused in options.render:
            fail(f"{refused} after --: the farm sets it", 2)
    if options.cache_prepass:
        first, last = parse_range(options.frames, "--frames")
        if first != last:
            fail("--cache-prepass: a cache file holds one frame; give --frames A:A", 2)
        for refused in ("--cache-in", "--cache-out"):
            if refused in options.render:
                fail(f"{refused} after --: --cache-prepass sets it", 2)
    if not options.scene.is_file():
        fail(f"{options.scene}: scene file not found", 2)
    return options


def split(first, last, size):
    """[first, last] in pieces of `size`: (a, b) pairs."""
    return [(a, min(a + size - 1, last)) for a in range(first, last + 1, size)]


def windows(width, height, columns, rows):
    """The --crop windows of a columns x rows split, row by row (None for a single tile)."""
    if columns == 1 and rows == 1:
        return [None]
    xs = [width * c // columns for c in range(columns + 1)]
    ys = [height * r // rows for r in range(rows + 1)]
    return [f"{xs[c]}:{xs[c + 1]},{ys[r]}:{ys[r + 1]}"
            for r in range(rows) for c in range(columns) if xs[c] < xs[c + 1] and ys[r] < ys[r + 1]]


def plan(options):
    """The tasks, each a dict with its name, frames, crop, samples and command."""
    out = options.out.resolve()
    radcache = str(options.bundle.resolve() / "radcache") if options.bundle else options.radcache
    first, last = parse_range(options.frames, "--frames")
    columns, rows = parse_tiles(options.tiles)
    spp, k = options.spp, options.sample_ranges
    ranges = [(spp * i // k, spp * (i + 1) // k) for i in range(k)]
    tasks = []
    for a, b in split(first, last, options.frames_per_task):
        for t, crop in enumerate(windows(options.width, options.height, columns, rows)):
            for s0, s1 in ranges:
                name = f"f{a}-{b}.t{t}.s{s0}-{s1}"
                start = max(first, a - options.pre_roll)  # the pre-roll: rendered, not written
                command = [radcache, "render", str(options.scene.resolve()), "--quiet",
                           "--frames", f"{start}:{b}", "-o",
                           str(out / "parts" / f"{name}.####.exr"),
                           "--width", str(options.width), "--height", str(options.height)]
                if start < a:
                    command += ["--write-from", str(a)]
                if b < last and "--temporal" in options.render:
                    # The task's frames are part of the clip: records placed ahead of them and
                    # their lives ended as in one process (radcache render --clip-end).
                    command += ["--clip-end", str(last)]
                # Sums (pt's) only where ranges are added: windows and frames need none.
                command += (["--sample-range", f"{s0}:{s1}", "--write-sums"] if k > 1
                            else ["--spp", str(spp)])
                if crop:
                    command += ["--crop", crop]
                command += options.render
                if options.cache_prepass:
                    command += ["--cache-in", str(out / "cache.rcc")]
                tasks.append({"name": name, "frames": (a, b), "command": command})
    return tasks


def group_parts(out, tasks, frames):
    """The part patterns of the tasks of frames (a, b)."""
    return [str(out / "parts" / f"{t['name']}.####.exr") for t in tasks if t["frames"] == frames]


def header(options, name, log):
    lines = ["#!/bin/bash", f"#SBATCH --job-name={name}", f"#SBATCH --output={log}",
             "#SBATCH --ntasks=1", "#SBATCH --cpus-per-task=1"]
    if options.partition:
        lines.append(f"#SBATCH --partition={options.partition}")
    return lines


def prepass_script(options):
    """The cache pre-pass: the frame whole, its cache written to DIR/cache.rcc."""
    out = options.out.resolve()
    radcache = str(options.bundle.resolve() / "radcache") if options.bundle else options.radcache
    first, _ = parse_range(options.frames, "--frames")
    command = [radcache, "render", str(options.scene.resolve()), "--quiet", "--frames",
               f"{first}:{first}", "-o", str(out / "prepass.exr"), "--width", str(options.width),
               "--height", str(options.height), "--spp", str(options.spp)] + options.render
    command += ["--cache-out", str(out / "cache.rcc")]
    lines = header(options, "radcache-prepass", out / "logs" / "prepass.log")
    if options.gpu:
        lines.append("#SBATCH --gres=gpu:1")
    lines += ["set -euo pipefail", shlex.join(command),
              f"touch {shlex.quote(str(out / 'done' / 'prepass'))}"]
    return "\n".join(lines) + "\n"


def render_script(options, tasks, indices):
    out = options.out.resolve()
    lines = header(options, "radcache-render", out / "logs" / "task-%a.log")
    lines.append(f"#SBATCH --array={','.join(str(i) for i in indices)}")
    lines.append("#SBATCH --kill-on-invalid-dep=yes")
    if options.gpu:
        lines.append("#SBATCH --gres=gpu:1")
    lines += ["set -euo pipefail", 'case "$SLURM_ARRAY_TASK_ID" in']
    for i in indices:
        lines.append(f"{i}) {shlex.join(tasks[i]['command'])} ;;")
    lines += ["*) echo \"no task $SLURM_ARRAY_TASK_ID\" >&2; exit 2 ;;", "esac",
              f'touch {shlex.quote(str(out / "done"))}/task-"$SLURM_ARRAY_TASK_ID"']
    return "\n".join(lines) + "\n"


def merge_script(options, tasks):
    out = options.out.resolve()
    radcache = str(options.bundle.resolve() / "radcache") if options.bundle else options.radcache
    lines = header(options, "radcache-merge", out / "logs" / "merge.log")
    lines += ["#SBATCH --kill-on-invalid-dep=yes", "set -euo pipefail"]
    # One merge a group of frames (the frames of a task): it holds them in memory at once.
    for frames in sorted({t["frames"] for t in tasks}):
        lines.append(shlex.join([radcache, "merge", "--quiet", "--frames",
                                 f"{frames[0]}:{frames[1]}", str(out / "frame.####.exr")]
                                + group_parts(out, tasks, frames)))
    lines.append(f"touch {shlex.quote(str(out / 'done' / 'merge'))}")
    return "\n".join(lines) + "\n"


def slurm(command, what):
    """Runs a Slurm command; one clear line when it is missing or the cluster does not answer."""
    if shutil.which(command[0]) is None:
        fail(f"{command[0]} not found: install slurm-client, or run on a Slurm login node "
             "(tools/farm/local-slurm.sh start runs a one-node cluster here)")
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=30)
    except subprocess.TimeoutExpired:
        fail(f"the Slurm cluster does not answer ({command[0]}: no reply in 30 s)")
    if result.returncode != 0:
        reason = (result.stderr.strip().splitlines() or ["no message"])[-1]
        fail(f"{what} failed: {reason}")
    return result.stdout


def submit(script_path, dependency=None):
    command = ["sbatch", "--parsable"]
    if dependency:
        command.append(f"--dependency=afterok:{dependency}")
    command.append(str(script_path))
    return slurm(command, f"sbatch {script_path.name}").strip().split(";")[0]


def follow(options, tasks, jobs):
    """Progress until the jobs leave the queue; returns the tasks that left no mark."""
    out = options.out.resolve()
    last = ""
    while True:
        listed = slurm(["squeue", "-h", "--states=PENDING,RUNNING,CONFIGURING,COMPLETING",
                        "-j", ",".join(jobs), "-o", "%T"], "squeue")
        states = listed.split()
        done = sum((out / "done" / f"task-{i}").exists() for i in range(len(tasks)))
        line = (f"farm: {done}/{len(tasks)} tasks done, {states.count('RUNNING')} running, "
                f"{states.count('PENDING')} pending")
        if line != last:
            print(line, flush=True)
            last = line
        if not states:
            break
        time.sleep(options.poll)
    return [i for i in range(len(tasks)) if not (out / "done" / f"task-{i}").exists()]


def report_failures(options, tasks, failed):
    out = options.out.resolve()
    for i in failed:
        log = out / "logs" / f"task-{i}.log"
        tail = ""
        if log.exists():
            lines = [line for line in log.read_text(errors="replace").splitlines() if line.strip()]
            tail = f": {lines[-1]}" if lines else ""
        print(f"farm: task {i} ({tasks[i]['name']}) failed; log {log}{tail}", file=sys.stderr)
    print(f"farm: {len(failed)} of {len(tasks)} tasks failed; run the same command again to "
          "render them", file=sys.stderr)


def prepare(options, tasks):
    """The farm's folders; Error when DIR holds a farm of other tasks."""
    out = options.out.resolve()
    for sub in ("scripts", "logs", "parts", "done"):
        (out / sub).mkdir(parents=True, exist_ok=True)
    listing = "\n".join(shlex.join(t["command"]) for t in tasks) + "\n"
    recorded = out / "tasks.txt"
    if recorded.exists() and recorded.read_text() != listing:
        fail(f"{out} holds a farm of other tasks (tasks.txt differs): use another --out", 2)
    recorded.write_text(listing)


def main(argv):
    options = arguments(argv)
    if not options.dry_run:  # the cluster asked before any task is built
        slurm(["sinfo", "-h", "-o", "%P"], "the Slurm cluster does not answer: sinfo")
    tasks = plan(options)
    out = options.out.resolve()
    if options.dry_run:
        if options.cache_prepass:
            print(f"# {out / 'scripts' / PREPASS}")
            print(prepass_script(options))
            print(f"# {out / 'scripts' / RENDER_ARRAY} (after the pre-pass: "
                  "--dependency=afterok:PREPASS)")
        else:
            print(f"# {out / 'scripts' / RENDER_ARRAY}")
        print(render_script(options, tasks, range(len(tasks))))
        print(f"# {out / 'scripts' / MERGE} (after the array: --dependency=afterok:ARRAY)")
        print(merge_script(options, tasks))
        return 0
    prepare(options, tasks)
    missing = [i for i in range(len(tasks)) if not (out / "done" / f"task-{i}").exists()]
    (out / "done" / "merge").unlink(missing_ok=True)
    jobs = []
    prepass = None
    if options.cache_prepass and missing and not (out / "done" / "prepass").exists():
        script = out / "scripts" / PREPASS
        script.write_text(prepass_script(options))
        prepass = submit(script)
        jobs.append(prepass)
        print(f"farm: submitted cache pre-pass job {prepass}", flush=True)
    array = None
    if missing:
        script = out / "scripts" / RENDER_ARRAY
        script.write_text(render_script(options, tasks, missing))
        array = submit(script, prepass)
        jobs.append(array)
        print(f"farm: submitted render array job {array} ({len(missing)} of {len(tasks)} "
              "tasks)", flush=True)
    merge = out / "scripts" / MERGE
    merge.write_text(merge_script(options, tasks))
    jobs.append(submit(merge, array))
    print(f"farm: submitted merge job {jobs[-1]}", flush=True)
    failed = follow(options, tasks, jobs)
    if prepass and not (out / "done" / "prepass").exists():
        fail(f"the cache pre-pass failed; log {out / 'logs' / 'prepass.log'}")
    if failed:
        report_failures(options, tasks, failed)
        return 1
    if not (out / "done" / "merge").exists():
        fail(f"the merge failed; log {out / 'logs' / 'merge.log'}")
    first, last = parse_range(options.frames, "--frames")
    print(f"farm: wrote {last - first + 1} frames to {out}/frame.####.exr")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
