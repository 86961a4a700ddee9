#!/usr/bin/env python3
"""Generates scenes/relief: fine geometric detail near large surfaces, the case where irradiance
caching crowds its records into corners and creases (the course's "Irradiance Decomposition",
"Previous Work"; Arikan et al. 2005, Fig. 2) and that irradiance decomposition was made for.

A 2 m box open at the front (z = 0), like the Cornell box: white floor, ceiling and back wall, a
red left wall (x = 1: the camera looks along +z) and a green right wall, one 0.5 m square area light under the ceiling. Its detail:

  scenes/relief/bricks.obj  a brick relief on the back wall: 0.24 x 0.09 m bricks standing
                            0.05 m proud of it, 0.02 m mortar joints, rows offset by half a brick
  scenes/relief/tiles.obj   a tiled floor: 0.18 m square tiles 0.025 m high, 0.02 m joints
  scenes/relief/sponge.obj  a Menger sponge of level 2 (0.54 m, 9^3 voxels, 400 of them filled)
                            standing on the tiles: the paper's own failure case for its near-field
                            visibility heuristic (its Fig. 5, "a deformed fractal in a Cornell
                            box": many small surfaces that hide one another)
  scenes/relief/scene.json  the scene (walls as built-in rectangles, the three meshes above)

Every box is written with only its faces that can be seen (a brick's back face lies on the wall,
a tile's bottom on the floor, the sponge's faces between two filled voxels are left out), so the
meshes are closed where they meet the walls and hold no hidden triangles. Vertices are shared
within a box. Deterministic: rerunning writes the same files. Standard library only.

Usage: python3 tools/make_relief_scene.py [--out DIR]   (default scenes/relief)
"""

import argparse
import os

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

BOX = 2.0  # the room: x in [-1, 1], y in [0, 2], z in [0, 2]; open at z = 0
BRICK = (0.24, 0.09, 0.05)  # width (x), height (y), depth out of the wall (z)
BRICK_JOINT = 0.02
TILE = 0.18
TILE_HEIGHT = 0.025
TILE_JOINT = 0.02
SPONGE_SIZE = 0.54
SPONGE_CORNER = (0.05, TILE_HEIGHT + 0.001, 0.85)  # its lower corner (x, y, z): 1 mm over the tiles

# The six faces of an axis-aligned box as (axis, side): the face whose outward normal is
# side * e_axis.
FACES = [(0, -1), (0, 1), (1, -1), (1, 1), (2, -1), (2, 1)]


class Mesh:
    def __init__(self):
        self.vertices = []
        self.index = {}
        self.faces = []

    def vertex(self, p):
        key = tuple(round(c, 6) for c in p)
        if key not in self.index:
            self.index[key] = len(self.vertices) + 1
            self.vertices.append(key)
        return self.index[key]

    def quad(self, corners):
        """Two triangles of a planar quad given counter-clockwise seen from its front."""
        a, b, c, d = (self.vertex(p) for p in corners)
        self.faces += [(a, b, c), (a, c, d)]

    def write(self, path, comment):
        with open(path, "w") as f:
            f.write("# %s\n# Written by tools/make_relief_scene.py.\n" % comment)
            for v in self.vertices:
                f.write("v %s\n" % " ".join("%.6g" % c for c in v))
            for t in self.faces:
                f.write("f %d %d %d\n" % t)


def box_face(lower, upper, axis, side):
    """The four corners of a face of the box [lower, upper], counter-clockwise seen from outside
    (the winding whose normal points out: the scene's front side)."""
    u, v = (axis + 1) % 3, (axis + 2) % 3
    fixed = upper[axis] if side > 0 else lower[axis]
    corners = []
    for (a, b) in [(0, 0), (1, 0), (1, 1), (0, 1)]:
        p = [0.0, 0.0, 0.0]
        p[axis] = fixed
        p[u] = upper[u] if a else lower[u]
        p[v] = upper[v] if b else lower[v]
        corners.append(tuple(p))
    # (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis.
    return corners if side > 0 else corners[::-1]


def add_box(mesh, lower, upper, skip=()):
    for axis, side in FACES:
        if (axis, side) not in skip:
            mesh.quad(box_face(lower, upper, axis, side))


def bricks():
    mesh = Mesh()
    w, h, d = BRICK
    row = 0
    y = BRICK_JOINT
    while y + h <= BOX - BRICK_JOINT + 1e-9:
        x = -BOX / 2 + BRICK_JOINT - (0.5 * (w + BRICK_JOINT) if row % 2 else 0.0)
        while x < BOX / 2 - BRICK_JOINT - 1e-9:
            left, right = max(x, -BOX / 2 + BRICK_JOINT), min(x + w, BOX / 2 - BRICK_JOINT)
            if right - left > 0.04:
                # Its back face (+z) lies on the back wall (z = BOX).
                add_box(mesh, (left, y, BOX - d), (right, y + h, BOX), skip=[(2, 1)])
            x += w + BRICK_JOINT
        y += h + BRICK_JOINT
        row += 1
    return mesh


def tiles():
    mesh = Mesh()
    count = int((BOX - TILE_JOINT) / (TILE + TILE_JOINT))
    margin = (BOX - count * (TILE + TILE_JOINT) + TILE_JOINT) / 2
    for i in range(count):
        for k in range(count):
            x = -BOX / 2 + margin + i * (TILE + TILE_JOINT)
            z = margin + k * (TILE + TILE_JOINT)
            # Its bottom face (-y) lies on the floor (y = 0).
            add_box(mesh, (x, 0.0, z), (x + TILE, TILE_HEIGHT, z + TILE), skip=[(1, -1)])
    return mesh


def menger_filled(level):
    """The filled voxels of a Menger sponge of `level` on a 3^level grid."""
    n = 3 ** level
    filled = set()
    for i in range(n):
        for j in range(n):
            for k in range(n):
                a, b, c, keep = i, j, k, True
                while a or b or c:
                    if [a % 3, b % 3, c % 3].count(1) >= 2:
                        keep = False
                        break
                    a, b, c = a // 3, b // 3, c // 3
                if keep:
                    filled.add((i, j, k))
    return n, filled


def sponge():
    mesh = Mesh()
    n, filled = menger_filled(2)
    cell = SPONGE_SIZE / n
    for (i, j, k) in sorted(filled):
        lower = tuple(SPONGE_CORNER[a] + cell * (i, j, k)[a] for a in range(3))
        upper = tuple(lower[a] + cell for a in range(3))
        skip = []
        for axis, side in FACES:
            neighbour = [i, j, k]
            neighbour[axis] += side
            if tuple(neighbour) in filled:
                skip.append((axis, side))
        add_box(mesh, lower, upper, skip=skip)
    return mesh, len(filled)


SCENE = """// The relief scene (written by tools/make_relief_scene.py): fine geometric detail near large
// surfaces, where irradiance caching crowds its records into corners and creases (Arikan et al.
// 2005, Fig. 2). A 2 m box open at the front: a brick relief on the back wall (bricks.obj), a
// tiled floor (tiles.obj), a Menger sponge of level 2 on it (sponge.obj; the paper's Fig. 5
// failure case for its visibility heuristic), red and green side walls, one area light.
{
    "camera": {
        "position": [0, 0.95, -1.5],
        "look_at": [0, 0.75, 1.2],
        "up": [0, 1, 0],
        "fov": 54,
        "resolution": [256, 256]
    },
    "materials": {
        "white": {"type": "diffuse", "reflectance": [0.73, 0.71, 0.68]},
        "red": {"type": "diffuse", "reflectance": [0.63, 0.065, 0.05]},
        "green": {"type": "diffuse", "reflectance": [0.14, 0.45, 0.091]},
        "mortar": {"type": "diffuse", "reflectance": [0.6, 0.58, 0.55]},
        "brick": {"type": "diffuse", "reflectance": [0.62, 0.32, 0.22]},
        "tile": {"type": "diffuse", "reflectance": [0.55, 0.55, 0.52]},
        "grout": {"type": "diffuse", "reflectance": [0.3, 0.3, 0.3]},
        "sponge": {"type": "diffuse", "reflectance": [0.75, 0.75, 0.75]},
        "light": {"type": "diffuse", "reflectance": [0.78, 0.78, 0.78]}
    },
    "shapes": [
        {"type": "rectangle", "name": "floor", "material": "grout",
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"translate": [0, 0, 1]}]},
        {"type": "rectangle", "name": "ceiling", "material": "white",
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}}, {"translate": [0, 2, 1]}]},
        {"type": "rectangle", "name": "back_wall", "material": "mortar",
         "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 180}}, {"translate": [0, 1, 2]}]},
        {"type": "rectangle", "name": "left_wall", "material": "red",
         "transform": [{"rotate": {"axis": [0, 1, 0], "angle": -90}}, {"translate": [1, 1, 1]}]},
        {"type": "rectangle", "name": "right_wall", "material": "green",
         "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 90}}, {"translate": [-1, 1, 1]}]},
        {"type": "obj", "name": "bricks", "file": "bricks.obj", "material": "brick"},
        {"type": "obj", "name": "tiles", "file": "tiles.obj", "material": "tile"},
        {"type": "obj", "name": "sponge", "file": "sponge.obj", "material": "sponge"},
        {"type": "rectangle", "name": "light", "material": "light",
         "emitter": {"type": "area", "radiance": [14, 12, 9]},
         "transform": [{"scale": 0.25}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                       {"translate": [0, 1.999, 1.0]}]}
    ],
    "render": {"spp": 64, "max_depth": 64, "rr_depth": 3}
}
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=os.path.join(ROOT, "scenes", "relief"))
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    b, t = bricks(), tiles()
    s, voxels = sponge()
    b.write(os.path.join(args.out, "bricks.obj"), "relief scene: bricks on the back wall")
    t.write(os.path.join(args.out, "tiles.obj"), "relief scene: floor tiles")
    s.write(os.path.join(args.out, "sponge.obj"),
            "relief scene: Menger sponge of level 2 (%d voxels)" % voxels)
    with open(os.path.join(args.out, "scene.json"), "w") as f:
        f.write(SCENE)
    print("bricks %d, tiles %d, sponge %d triangles -> %s" % (
        len(b.faces), len(t.faces), len(s.faces), args.out))


if __name__ == "__main__":
    main()
