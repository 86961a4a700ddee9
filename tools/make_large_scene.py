#!/usr/bin/env python3
"""Writes a generated scene of at least N triangles (docs/reliability.md, "Large scenes"): a grid of
built-in spheres (9 024 triangles each after the poles' degenerate ones are dropped) on a floor
under an area light, seen from above at an angle.

    tools/make_large_scene.py OUT.json [--triangles 5000000]
"""
import argparse
import json
import math

from radcache_tools.arguments import positive_int

TRIANGLES_PER_SPHERE = 9024  # make_uv_sphere(rings 48, segments 96) once loaded


def scene(triangles):
    spheres = math.ceil(triangles / TRIANGLES_PER_SPHERE)
    side = math.ceil(math.sqrt(spheres))
    shapes = [
        {"type": "rectangle", "name": "floor", "material": "floor",
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}},
                       {"scale": [side, 1, side]}]},
        {"type": "rectangle", "name": "light", "emitter": {"type": "area", "radiance": 4},
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}},
                       {"scale": [side / 4, 1, side / 4]}, {"translate": [0, side, 0]}]},
    ]
    for i in range(spheres):
        x, z = i % side, i // side
        shapes.append({"type": "sphere", "name": "s%d" % i,
                       "material": "glossy" if (x + z) % 3 == 0 else "matte",
                       "center": [2 * x - side + 1, 0.8, 2 * z - side + 1], "radius": 0.8})
    return {
        "camera": {"position": [0, 1.2 * side, 1.6 * side], "look_at": [0, 0, 0], "fov": 50,
                   "resolution": [64, 64]},
        "materials": {
            "floor": {"type": "diffuse", "reflectance": 0.6},
            "matte": {"type": "diffuse", "reflectance": [0.6, 0.4, 0.3]},
            "glossy": {"type": "phong", "diffuse": 0.2, "specular": 0.4, "exponent": 30},
        },
        "shapes": shapes,
        "render": {"spp": 1},
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out")
    parser.add_argument("--triangles", type=positive_int, default=5_000_000)
    args = parser.parse_args()
    try:
        with open(args.out, "w") as out:
            json.dump(scene(args.triangles), out, indent=1)
            out.write("\n")
    except OSError as e:
        parser.error("%s: %s" % (args.out, e.strerror))


if __name__ == "__main__":
    main()
