"""Where a shipped scene's path-traced reference lies, and the record of how it was made.

Layout (scenes/README.md): a still scene's reference is scenes/NAME/reference.exr; an animated
scene (animation.frame_end > frame_start in its scene.json) has one per frame,
scenes/NAME/reference/frameFFFF.exr (four digits), and no reference.exr. Beside every reference
EXR lies a JSON record of the same stem (reference.json, frameFFFF.json): how it was made, and
the `spp` that `radcache compare` reads for the relMSE net of the reference's noise.

As a library: frame_range(scene_json), reference_path(scene_dir, frame) and the shipped scenes'
best references. As a command (tools/references.py, run by tools/render-references.sh), writes
the records of one render from its --stats:

  tools/references.py record STATS --scene SCENE_DIR --dest DIR --command "radcache render ..."
      [--git REVISION] [--date YYYY-MM-DD]

DIR/reference.json for a still scene, DIR/reference/frameFFFF.json for every frame of an
animated one (DIR is usually SCENE_DIR). Standard library only.
"""

import argparse
import datetime
import json
import os
import subprocess
import sys

from radcache_tools import ROOT

LAYERS = "beauty (R, G, B), direct, indirect, stddev (of one beauty sample of the pixel)"


class ReferenceError(Exception):
    """A reference that cannot be named: the message says which scene, frame or file."""


def strip_comments(text):
    """The JSON text of a scene file without its // and /* */ comments (docs/scene-format.md),
    string literals left as they are."""
    out = []
    i = 0
    in_string = False
    while i < len(text):
        c = text[i]
        if in_string:
            out.append(c)
            if c == "\\" and i + 1 < len(text):
                out.append(text[i + 1])
                i += 1
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
            out.append(c)
        elif text.startswith("//", i):
            end = text.find("\n", i)
            i = len(text) if end < 0 else end
            continue
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            if end < 0:
                raise ReferenceError("unterminated /* comment")
            i = end + 2
            continue
        else:
            out.append(c)
        i += 1
    return "".join(out)


def load_scene_json(scene_json):
    try:
        with open(scene_json) as f:
            return json.loads(strip_comments(f.read()))
    except (OSError, ValueError, ReferenceError) as e:
        raise ReferenceError("%s: %s" % (scene_json, e))


def frame_range(scene_json):
    """(frame_start, frame_end) of a scene: (0, 0) without an animation block."""
    animation = load_scene_json(scene_json).get("animation") or {}
    start = int(animation.get("frame_start", 0))
    return start, int(animation.get("frame_end", start))


def is_animated(scene_json):
    start, end = frame_range(scene_json)
    return end > start


def reference_name(animated, frame):
    """The reference's path relative to its scene's folder."""
    return os.path.join("reference", "frame%04d.exr" % frame) if animated else "reference.exr"


def reference_path(scene_dir, frame=None):
    """The reference EXR of a scene's frame (default: frame_start, the frame a render without
    --frames shows), whether or not it exists; ReferenceError for a frame outside the scene."""
    scene_json = os.path.join(scene_dir, "scene.json")
    start, end = frame_range(scene_json)
    frame = start if frame is None else frame
    if not start <= frame <= end:
        raise ReferenceError("%s: frame %d is outside the scene's frames %d:%d" %
                             (scene_dir, frame, start, end))
    return os.path.join(scene_dir, reference_name(end > start, frame))


SHARED_REFERENCES = os.path.normpath(os.path.join(ROOT, "..", "shared", "references"))


def best_reference_path(scene_dir):
    """A still scene's least noisy reference: the 65 536-spp one of ../shared/references
    (NAME.exr) where there is one, else its shipped reference.exr."""
    shared = os.path.join(SHARED_REFERENCES, os.path.basename(os.path.normpath(scene_dir)) + ".exr")
    return shared if os.path.exists(shared) else reference_path(scene_dir)


def shipped_scene_json(scene):
    """scenes/NAME/scene.json of a shipped scene."""
    return os.path.join(ROOT, "scenes", scene, "scene.json")


def camera_size(scene_json, width):
    """(width, the height that keeps the scene camera's aspect)."""
    w, h = load_scene_json(scene_json)["camera"].get("resolution", [512, 512])
    return width, max(1, round(width * h / w))


def require_references(parser, scenes):
    """Stops `parser` with one line for a shipped scene (scenes/NAME) that does not exist or has
    no reference (the benchmark scripts' --scenes)."""
    for scene in scenes:
        try:
            reference = reference_path(os.path.join(ROOT, "scenes", scene))
        except ReferenceError as e:
            parser.error("--scenes %s: %s" % (scene, e))
        if not os.path.isfile(reference):
            parser.error("--scenes %s: the scene has no reference (%s)" % (scene, reference))


def record(stats, scene_dir, dest, command, git, date):
    """The records of one reference render: {path: record} for every frame in its --stats."""
    animated = is_animated(os.path.join(scene_dir, "scene.json"))
    frames = stats["frames"]
    if not animated and len(frames) != 1:
        raise ReferenceError("%s is a still scene, but the stats hold %d frames" %
                             (scene_dir, len(frames)))
    records = {}
    for entry in frames:
        name = reference_name(animated, entry["frame"])
        records[os.path.join(dest, os.path.splitext(name)[0] + ".json")] = {
            "file": os.path.basename(name),
            "layers": LAYERS,
            "storage": "OpenEXR, half float, zip",
            "method": stats["method"],
            "spp": entry["spp"],
            "seed": stats["seed"],
            "frame": entry["frame"],
            "resolution": stats["resolution"],
            "max_depth": stats["max_depth"],
            "command": command,
            "git": git,
            "date": date,
            "device": stats["device"],
            # This frame's render; the run's render phase and whole process (one run renders
            # every frame of an animated scene).
            "seconds": {"frame": round(entry["seconds"], 2),
                        "run_render": round(stats["seconds"]["render"], 2),
                        "run_total": round(stats["seconds"]["total"], 2)},
            "rays": entry["rays"],
            "run_rays": stats["rays"],
            "run_frames": [frames[0]["frame"], frames[-1]["frame"]],
            "nonfinite_samples": stats["nonfinite_samples"],  # over the whole run
        }
    return records


def git_revision():
    result = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True)
    revision = result.stdout.strip() or "unknown"
    dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip()
    return revision + ("-dirty" if dirty else "")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    commands = parser.add_subparsers(dest="action", required=True)
    write = commands.add_parser("record", help="write the records of one reference render")
    write.add_argument("stats", help="the render's --stats JSON")
    write.add_argument("--scene", required=True, help="the scene's folder (scenes/NAME)")
    write.add_argument("--dest", required=True, help="folder that receives the reference")
    write.add_argument("--command", required=True, help="the radcache command line, as run")
    write.add_argument("--git", help="radcache's git revision (default: this checkout's)")
    write.add_argument("--date", help="YYYY-MM-DD (default: today, UTC)")
    args = parser.parse_args(argv)
    try:
        with open(args.stats) as f:
            stats = json.load(f)
    except (OSError, ValueError) as e:
        sys.exit("references: %s: %s" % (args.stats, e))
    date = args.date or datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d")
    try:
        records = record(stats, args.scene, args.dest, args.command,
                         args.git or git_revision(), date)
    except KeyError as e:
        sys.exit("references: %s: no key %s (not a radcache render --stats file?)" %
                 (args.stats, e))
    except ReferenceError as e:
        sys.exit("references: %s: %s" % (args.stats, e))
    for path, content in records.items():
        os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
        with open(path, "w") as f:
            json.dump(content, f, indent=2)
            f.write("\n")
