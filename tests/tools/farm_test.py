#!/usr/bin/env python3
"""tools/farm.py and tools/farm/local-slurm.sh (docs/farm.md). Without Slurm: the dry run's
scripts (the array, the merge after it by afterok, --gres with --gpu) and one clear line when
sbatch is missing or the controller does not answer, and a farm no task could render (a range of more
tasks than a Slurm array holds, an empty image, a negative poll) refused before any task is built. On the local one-node cluster (tools/farm/local-slurm.sh start; skipped, saying
so, only when no cluster answers): a 6-frame clip split 2 frames a task is bitwise the clip of one
process; the Cornell box split into 4 sample ranges merges to the single render (beauty within
relative 1e-6 of its value, the stddev layer within 1e-4, by OpenImageIO's idiff); a task killed mid-render is reported
by name and log, and a second call renders only it, the frames then right; 2x2 tiles merge to
the single render bitwise, and a part of another scene is refused; ic tiles rendered with the
cache of a pre-pass job merge to the single render bitwise; `ic --temporal` tasks with the
whole clip as pre-roll give every frame of a 6-frame clip bitwise as one process (and without it,
not). Run by CTest with
$RADCACHE set to the built executable."""

import os
import shutil
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
FARM = os.path.join(ROOT, "tools", "farm.py")
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")
SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp", "farm_test")
CORNELL = os.path.join(ROOT, "scenes", "cornell-box", "scene.json")
SPHERE = os.path.join(ROOT, "scenes", "moving-sphere", "scene.json")


def slurm_answers():
    if shutil.which("sinfo") is None:
        return False
    try:
        result = subprocess.run(["sinfo", "-h", "-o", "%T"], capture_output=True, text=True,
                                timeout=20)
    except subprocess.TimeoutExpired:
        return False
    return result.returncode == 0 and result.stdout.strip() != ""


def farm(args, env=None):
    return subprocess.run([sys.executable, FARM, "--radcache", RADCACHE, "--poll", "0.5"] + args,
                          capture_output=True, text=True, env=env, timeout=900)


def differs(a, b, channels, relative, scratch):
    """Where the channels of .exr files a and b differ (OpenImageIO's idiff: a pixel fails where
    a channel differs by more than `relative` times its value; 0: any difference), or ''."""
    picked = []
    for name, path in (("a", a), ("b", b)):
        picked.append(os.path.join(scratch, f"{name}-layer.exr"))
        subprocess.run(["oiiotool", path, "--ch", channels, "-o", picked[-1]], check=True)
    result = subprocess.run(["idiff", "-fail", "0", "-warn", "0", "-failrelative", str(relative),
                             "-warnrelative", str(relative)] + picked,
                            capture_output=True, text=True)
    return "" if result.returncode == 0 else result.stdout


def render(args):
    result = subprocess.run([RADCACHE, "render", "--quiet"] + args, capture_output=True,
                            text=True)
    assert result.returncode == 0, result.stdout + result.stderr


class FarmWithoutSlurm(unittest.TestCase):
    def test_dry_run_ties_the_merge_to_the_array(self):
        result = farm([SPHERE, "--out", os.path.join(SCRATCH, "dry"), "--frames", "0:5",
                       "--frames-per-task", "2", "--tiles", "2x1", "--width", "32", "--height",
                       "32", "--spp", "4", "--gpu", "--dry-run"])
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("#SBATCH --array=0,1,2,3,4,5", result.stdout)
        self.assertIn("#SBATCH --gres=gpu:1", result.stdout)
        self.assertIn("--dependency=afterok", result.stdout)
        self.assertIn("--crop 16:32,0:32", result.stdout)
        self.assertEqual(result.stdout.count(" merge --quiet --frames "), 3)
        self.assertIn("--frames 2:3 ", result.stdout)

    def test_a_missing_sbatch_is_one_line(self):
        bare = os.path.join(SCRATCH, "bare-path")
        os.makedirs(bare, exist_ok=True)
        result = farm([CORNELL, "--out", os.path.join(SCRATCH, "nosbatch"), "--width", "8",
                       "--height", "8"], env=dict(os.environ, PATH=bare))
        self.assertEqual(result.returncode, 1)
        self.assertEqual(result.stderr.count("\n"), 1, result.stderr)
        self.assertIn("not found", result.stderr)


    def test_what_no_task_could_render_is_refused_before_any_task_is_built(self):
        for args, expected in (
                (["--frames", "0:20000000"], "20000001 tasks, more than a Slurm array holds"),
                (["--width", "0"], "--width 0 --height 8: must be at least 1"),
                (["--poll", "-1"], "--poll -1.0: must be a positive number of seconds")):
            base = [CORNELL, "--out", os.path.join(SCRATCH, "refused"), "--width", "8",
                    "--height", "8", "--dry-run"]
            result = subprocess.run([sys.executable, FARM, "--radcache", RADCACHE] + base + args,
                                    capture_output=True, text=True, timeout=60)
            self.assertEqual(result.returncode, 2, result.stderr)
            self.assertEqual(result.stderr.count("\n"), 1, result.stderr)
            self.assertIn(expected, result.stderr)

    @unittest.skipUnless(shutil.which("sinfo"), "no Slurm client (sinfo)")
    def test_a_cluster_that_does_not_answer_is_one_line(self):
        conf = os.path.join(SCRATCH, "dead-slurm.conf")
        with open(conf, "w") as file:
            file.write("ClusterName=dead\nSlurmctldHost=localhost(127.0.0.1)\n"
                       "SlurmctldPort=6999\nNodeName=dead CPUs=1 State=UNKNOWN\n"
                       "PartitionName=dead Nodes=dead Default=YES\n")
        result = farm([CORNELL, "--out", os.path.join(SCRATCH, "dead"), "--width", "8",
                       "--height", "8"], env=dict(os.environ, SLURM_CONF=conf))
        self.assertEqual(result.returncode, 1)
        self.assertEqual(result.stderr.count("\n"), 1, result.stderr)
        self.assertIn("farm: the Slurm cluster does not answer", result.stderr)


@unittest.skipUnless(slurm_answers(), "Slurm is not running: tools/farm/local-slurm.sh start")
class FarmOnLocalSlurm(unittest.TestCase):
    def setUp(self):
        self.dir = os.path.join(SCRATCH, self.id().split(".")[-1])
        shutil.rmtree(self.dir, ignore_errors=True)
        os.makedirs(self.dir)

    def test_frames_are_bitwise_those_of_one_process(self):
        out = os.path.join(self.dir, "farm")
        result = farm([SPHERE, "--out", out, "--frames", "0:5", "--frames-per-task", "2",
                       "--width", "32", "--height", "32", "--spp", "4"])
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("3/3 tasks done", result.stdout)
        render([SPHERE, "--frames", "0:5", "--width", "32", "--height", "32", "--spp", "4",
                "--write-sums", "-o", os.path.join(self.dir, "one.####.exr")])
        for frame in range(6):
            one = os.path.join(self.dir, f"one.{frame:04d}.exr")
            farmed = os.path.join(out, f"frame.{frame:04d}.exr")
            for channels in ("R,G,B", "stddev.R,stddev.G,stddev.B", "albedo.R,albedo.G,albedo.B"):
                self.assertEqual(differs(farmed, one, channels, 0, self.dir), "",
                                 f"frame {frame} {channels}")

    def test_temporal_tasks_with_a_whole_pre_roll_are_those_of_one_process(self):
        one = os.path.join(self.dir, "one.####.exr")
        render([SPHERE, "--method", "ic", "--temporal", "--frames", "0:5", "--width", "16",
                "--height", "16", "--spp", "2", "-o", one])
        farmed = {}
        for pre_roll in ("0", "6"):
            out = os.path.join(self.dir, "farm" + pre_roll)
            result = farm([SPHERE, "--out", out, "--frames", "0:5", "--frames-per-task", "2",
                           "--pre-roll", pre_roll, "--width", "16", "--height", "16", "--spp",
                           "2", "--", "--method", "ic", "--temporal"])
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            # The second task's warm-up frames 0-1 are not among its parts.
            self.assertEqual(sorted(f for f in os.listdir(os.path.join(out, "parts"))
                                    if f.startswith("f2-3")),
                             ["f2-3.t0.s0-2.0002.exr", "f2-3.t0.s0-2.0003.exr"])
            farmed[pre_roll] = os.path.join(out, "frame.####.exr")
        # With the whole clip as pre-roll (and each task told where the clip ends), every frame
        # bitwise one process's, the last of each task included; without it the second task's
        # records start afresh at frame 2, and its image differs.
        for frame in range(6):
            self.assertEqual(differs(farmed["6"].replace("####", f"{frame:04d}"),
                                     one.replace("####", f"{frame:04d}"), "R,G,B", 0, self.dir),
                             "", f"frame {frame}")
        self.assertNotEqual(differs(farmed["0"].replace("####", "0002"),
                                    one.replace("####", "0002"), "R,G,B", 0, self.dir), "")

    def test_sample_ranges_merge_to_the_single_render(self):
        out = os.path.join(self.dir, "farm")
        result = farm([CORNELL, "--out", out, "--sample-ranges", "4", "--spp", "64", "--width",
                       "24", "--height", "24"])
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        one = os.path.join(self.dir, "one.exr")
        render([CORNELL, "--width", "24", "--height", "24", "--spp", "64", "--write-sums",
                "-o", one])
        merged = os.path.join(out, "frame.0000.exr")
        # Not bitwise: the single render adds its 64 samples one by one in float32.
        self.assertNotEqual(differs(merged, one, "R,G,B", 0, self.dir), "")
        for channels, bound in (("R,G,B", 1e-6), ("stddev.R,stddev.G,stddev.B", 1e-4)):
            self.assertEqual(differs(merged, one, channels, bound, self.dir), "", channels)

    def test_tiles_merge_to_the_single_render_bitwise_and_another_scene_is_refused(self):
        out = os.path.join(self.dir, "farm")
        result = farm([CORNELL, "--out", out, "--tiles", "2x2", "--spp", "4", "--width", "24",
                       "--height", "20"])
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("4/4 tasks done", result.stdout)
        one = os.path.join(self.dir, "one.exr")
        render([CORNELL, "--width", "24", "--height", "20", "--spp", "4", "--write-sums",
                "-o", one])
        merged = os.path.join(out, "frame.0000.exr")
        for channels in ("R,G,B", "stddev.R,stddev.G,stddev.B", "normal.R,normal.G,normal.B"):
            self.assertEqual(differs(merged, one, channels, 0, self.dir), "", channels)
        # A window of another scene, rendered as the farm's tasks are, is refused by name.
        other = os.path.join(self.dir, "furnace-part.exr")
        furnace = os.path.join(ROOT, "scenes", "furnace", "scene.json")
        render([furnace, "--width", "24", "--height", "20", "--spp", "4", "--write-sums",
                "--frames", "0:0", "--crop", "12:24,10:20", "-o", other])
        parts = sorted(os.path.join(out, "parts", name) for name in os.listdir(
            os.path.join(out, "parts")))
        target = os.path.join(self.dir, "mixed.exr")
        mixed = subprocess.run([RADCACHE, "merge", target] + parts[:3] + [other],
                               capture_output=True, text=True)
        self.assertNotEqual(mixed.returncode, 0)
        self.assertIn("furnace-part.exr: another scene (its file or a file it reads)", mixed.stderr)
        self.assertEqual(mixed.stderr.count("\n"), 1, mixed.stderr)
        self.assertFalse(os.path.exists(target))

    def test_ic_tiles_with_a_cache_prepass_show_no_seams(self):
        out = os.path.join(self.dir, "farm")
        result = farm([CORNELL, "--out", out, "--tiles", "2x2", "--spp", "2", "--width", "24",
                       "--height", "24", "--cache-prepass", "--", "--method", "ic"])
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("cache pre-pass job", result.stdout)
        # The tiles, each rendered with the pre-pass's cache, merge to bitwise the image of one
        # render with that cache and to the pre-pass's own image.
        one = os.path.join(self.dir, "one.exr")
        render([CORNELL, "--method", "ic", "--width", "24", "--height", "24", "--spp", "2",
                "--cache-in", os.path.join(out, "cache.rcc"), "-o", one])
        merged = os.path.join(out, "frame.0000.exr")
        for reference in (one, os.path.join(out, "prepass.exr")):
            for channels in ("R,G,B", "indirect.R,indirect.G,indirect.B"):
                self.assertEqual(differs(merged, reference, channels, 0, self.dir), "",
                                 f"{reference} {channels}")

    def test_a_killed_task_is_reported_and_rendered_again(self):
        # The radcache the tasks run: task f2-3's first attempt is killed mid-render.
        flag = os.path.join(self.dir, "killed-once")
        wrapper = os.path.join(self.dir, "radcache-wrapper.sh")
        with open(wrapper, "w") as file:
            file.write(f"""#!/bin/bash
if [[ "$*" == *"--frames 2:3"* && ! -e {flag} ]]; then
    touch {flag}
    {RADCACHE} "$@" & sleep 0.3; kill -9 $!; exit 137
fi
exec {RADCACHE} "$@"
""")
        os.chmod(wrapper, 0o755)
        out = os.path.join(self.dir, "farm")
        args = [SPHERE, "--out", out, "--frames", "0:5", "--frames-per-task", "2", "--width",
                "32", "--height", "32", "--spp", "4"]
        first = subprocess.run([sys.executable, FARM, "--radcache", wrapper, "--poll", "0.5"]
                               + args, capture_output=True, text=True, timeout=900)
        self.assertEqual(first.returncode, 1, first.stdout + first.stderr)
        self.assertIn("task 1 (f2-3.t0.s0-4) failed; log", first.stderr)
        self.assertIn("task-1.log", first.stderr)
        self.assertFalse(os.path.exists(os.path.join(out, "frame.0000.exr")))
        second = subprocess.run([sys.executable, FARM, "--radcache", wrapper, "--poll", "0.5"]
                                + args, capture_output=True, text=True, timeout=900)
        self.assertEqual(second.returncode, 0, second.stdout + second.stderr)
        self.assertIn("(1 of 3 tasks)", second.stdout)
        render([SPHERE, "--frames", "2:3", "--width", "32", "--height", "32", "--spp", "4",
                "--write-sums", "-o", os.path.join(self.dir, "one.####.exr")])
        for frame in (2, 3):
            self.assertEqual(differs(os.path.join(out, f"frame.{frame:04d}.exr"),
                                     os.path.join(self.dir, f"one.{frame:04d}.exr"), "R,G,B", 0,
                                     self.dir), "")


if __name__ == "__main__":
    shutil.rmtree(SCRATCH, ignore_errors=True)
    os.makedirs(SCRATCH, exist_ok=True)
    unittest.main()
