#!/usr/bin/env python3
"""An independent check of a shipped reference: Mitsuba 3's path tracer against radcache's.

Renders the scene twice with Mitsuba (render.py, seeds 0 and 1, --spp each) at the reference's
resolution and reports, for the mean M of the two images against the reference R:

  per-channel means of M and R and their relative difference;
  relMSE = mean over pixels and channels of (M - R)^2 / (R^2 + 0.01);
  net relMSE = relMSE minus both images' own noise: the reference's stddev^2/spp_ref (its stddev
  layer and the spp of reference.json) and Mitsuba's (A - B)^2 / 4 (the variance of the mean of
  two independent images), each over R^2 + 0.01. What is left is the images' disagreement.

Prints one JSON object (and writes it to --json). Needs mitsuba and numpy.

Usage: tools/peers/mitsuba/check_reference.py SCENE [--spp N] [--out DIR] [--json FILE]
"""

import argparse
import json
import os
import subprocess
import sys

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
from radcache_tools import error
from radcache_tools.arguments import positive_int


def layer(bitmap_path, prefix):
    """An EXR layer (prefix "" for R, G, B) as an (H, W, 3) array, through Mitsuba's Bitmap."""
    import mitsuba as mi
    channels = {}
    for name, image in mi.Bitmap(bitmap_path).split():
        channels[name] = numpy.array(image)
    names = [prefix + c for c in ("R", "G", "B")]
    if all(n in channels for n in names):
        return numpy.stack([channels[n][..., 0] for n in names], axis=-1).astype(numpy.float64)
    base = "<root>" if prefix == "" else prefix.rstrip(".")
    return numpy.array(channels[base])[..., :3].astype(numpy.float64)


def render(scene, image, spp, seed):
    command = [sys.executable, os.path.join(HERE, "render.py"), scene, image, "--spp", str(spp),
               "--seed", str(seed)]
    subprocess.run(command, check=True)
    with open(os.path.splitext(image)[0] + ".json") as f:
        return json.load(f)


def figures(a, b, reference, stddev, spp_ref):
    m = 0.5 * (a + b)
    relmse = error.relmse_of_arrays(m, reference)
    reference_noise = error.noise_of_arrays(reference, stddev, spp_ref)
    # The variance of the mean of two independent images, (A - B)^2 / 4: a standard deviation
    # |A - B| / 2 of one "sample".
    own_noise = error.noise_of_arrays(reference, numpy.abs(a - b) / 2.0, 1)
    means = m.reshape(-1, 3).mean(axis=0)
    ref_means = reference.reshape(-1, 3).mean(axis=0)
    return {"means": means.tolist(), "reference_means": ref_means.tolist(),
            "relative_difference": (means / ref_means - 1.0).tolist(), "relmse": relmse,
            "reference_noise": reference_noise, "mitsuba_noise": own_noise,
            "relmse_net": relmse - reference_noise - own_noise}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene", help="scene directory (with reference.exr and reference.json)")
    parser.add_argument("--spp", type=positive_int, default=256)
    parser.add_argument("--out", default="build/peers/mitsuba-check")
    parser.add_argument("--json")
    args = parser.parse_args(argv)
    for needed in ("reference.exr", "reference.json"):
        if not os.path.isfile(os.path.join(args.scene, needed)):
            parser.error("%s: no %s (a scene directory with its reference)" % (args.scene, needed))
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    reference_path = os.path.join(args.scene, "reference.exr")
    with open(os.path.join(args.scene, "reference.json")) as f:
        spp_ref = json.load(f)["spp"]
    os.makedirs(args.out, exist_ok=True)
    name = os.path.basename(os.path.normpath(args.scene))
    images = [os.path.join(args.out, "%s-seed%d.exr" % (name, seed)) for seed in (0, 1)]
    records = [render(args.scene, image, args.spp, seed) for seed, image in enumerate(images)]
    result = figures(layer(images[0], ""), layer(images[1], ""), layer(reference_path, ""),
                     layer(reference_path, "stddev."), spp_ref)
    result.update({"scene": name, "spp": args.spp, "images": 2, "reference_spp": spp_ref,
                   "render_seconds": [r["render_seconds"] for r in records],
                   "mitsuba": records[0]["mitsuba"], "variant": records[0]["variant"]})
    text = json.dumps(result, indent=2)
    print(text)
    if args.json:
        with open(args.json, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main(sys.argv[1:])
