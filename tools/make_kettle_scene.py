#!/usr/bin/env python3
"""Generates the meshes and texture of scenes/kettle (the kettle scene of Gassenbauer et al. 2009,
"Spatial Directional Radiance Caching", §5, in our own version):

  scenes/kettle/kettle.obj   a kettle: body and lid knob as surfaces of revolution about +y, a
                             spout (a bent, tapered tube) towards +x and a handle (a tube along a
                             circular arc) towards -x; the body's base at y ≈ 0, its largest
                             radius 1 (the scene scales it); per-vertex normals and uvs
  scenes/kettle/checker.png  a 4 x 4 checkerboard, linear reflectances 0.8 (cream) and 0.08
                             (dark blue), sRGB-encoded, 256 x 256; 4 x 4 rather than finer, so
                             that a 2 m wall's 0.5 m squares stay visible in the kettle's
                             reflection, blurred by alpha_x 0.18 and shrunk by its curvature

uvs: on the body and knob u runs around the axis and v along the profile (bottom to top); on the
tubes u runs around the tube and v along it. A Ward material's alpha_x follows u
(docs/scene-format.md), so the kettle's rougher direction is around the body.

Deterministic: rerunning writes the same files. numpy and the standard library only.
Usage: python3 tools/make_kettle_scene.py [--out DIR]   (default scenes/kettle)
"""

import argparse
import os
import struct
import zlib

import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

# Profiles (radius, height) from the bottom on the axis to the top on the axis, through which a
# Catmull-Rom spline passes: a squat rounded body whose shoulder rises to a domed lid.
BODY_PROFILE = [(0.0, 0.0), (0.55, 0.0), (0.82, 0.03), (0.96, 0.16), (1.0, 0.36), (0.95, 0.57),
                (0.8, 0.76), (0.6, 0.88), (0.47, 0.93), (0.45, 0.97), (0.36, 1.02),
                (0.2, 1.055), (0.0, 1.065)]
KNOB_PROFILE = [(0.0, 1.055), (0.1, 1.06), (0.07, 1.1), (0.09, 1.15), (0.13, 1.2), (0.08, 1.24),
                (0.0, 1.25)]


def catmull_rom(points, samples_per_segment=64):
    """A dense polyline through the points (end points repeated as their own tangents' guides)."""
    p = np.array(points, dtype=float)
    p = np.vstack([p[0], p, p[-1]])
    t = np.linspace(0.0, 1.0, samples_per_segment, endpoint=False)[:, None]
    out = []
    for i in range(1, len(p) - 2):
        p0, p1, p2, p3 = p[i - 1], p[i], p[i + 1], p[i + 2]
        out.append(0.5 * (2 * p1 + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t**2
                          + (3 * p1 - p0 - 3 * p2 + p3) * t**3))
    out.append(p[-2][None, :])
    return np.vstack(out)


def resample(polyline, n, bend=0.5):
    """n + 1 points along a polyline, spaced evenly in arc length plus bend x turning angle (so
    that curved parts get more of them), and their arc-length fraction (the texture v)."""
    step = np.diff(polyline, axis=0)
    length = np.concatenate([[0.0], np.cumsum(np.linalg.norm(step, axis=1))])
    heading = np.unwrap(np.arctan2(step[:, 1], step[:, 0]))
    turn = np.concatenate([[0.0, 0.0], np.cumsum(np.abs(np.diff(heading)))])
    measure = length + bend * turn
    m = np.linspace(0.0, measure[-1], n + 1)
    points = np.stack([np.interp(m, measure, polyline[:, k]) for k in range(2)], axis=1)
    return points, np.interp(m, measure, length) / length[-1]


class Mesh:
    """Vertices with normals and uvs, and triangles; grids of (rows + 1) x (cols + 1) vertices."""

    def __init__(self):
        self.v, self.n, self.uv, self.tri = [], [], [], []
        self.count = 0

    def add_grid(self, pos, nrm, uv):
        """pos, nrm: (rows + 1, cols + 1, 3); uv: (rows + 1, cols + 1, 2). Quads split in two,
        wound counter-clockwise seen from the side the normals point to; zero-area triangles
        (where a row collapses onto the axis) are left out."""
        rows, cols = pos.shape[0] - 1, pos.shape[1] - 1
        base = self.count
        self.v.append(pos.reshape(-1, 3))
        self.n.append(nrm.reshape(-1, 3) / np.linalg.norm(nrm.reshape(-1, 3), axis=1)[:, None])
        self.uv.append(uv.reshape(-1, 2))
        i, j = np.meshgrid(np.arange(rows), np.arange(cols), indexing="ij")
        a, b = i * (cols + 1) + j, i * (cols + 1) + j + 1
        c, d = b + cols + 1, a + cols + 1
        tri = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                              np.stack([a, c, d], -1).reshape(-1, 3)])
        p, n = pos.reshape(-1, 3)[tri], self.n[-1][tri]
        cross = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
        tri = np.where((np.einsum("ij,ij->i", cross, n.sum(axis=1)) < 0)[:, None],
                       tri[:, [0, 2, 1]], tri)
        tri = tri[np.linalg.norm(cross, axis=1) > 1e-12]
        self.tri.append(tri + base)
        self.count += (rows + 1) * (cols + 1)

    def triangles(self):
        return sum(len(t) for t in self.tri)

    def write_obj(self, path, header):
        v, n, uv, tri = (np.vstack(x) for x in (self.v, self.n, self.uv, self.tri))
        lines = ["# " + line for line in header]
        v, n, uv = (np.round(x, 6) + 0.0 for x in (v, n, uv))  # + 0.0: no "-0.000000"
        lines += ["v %.6f %.6f %.6f" % tuple(p) for p in v]
        lines += ["vn %.6f %.6f %.6f" % tuple(p) for p in n]
        lines += ["vt %.6f %.6f" % tuple(p) for p in uv]
        lines += ["f %d/%d/%d %d/%d/%d %d/%d/%d" % tuple(k + 1 for k in t for _ in range(3))
                  for t in tri]
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")


def revolution(mesh, profile, around, along):
    """A surface of revolution about +y of a (radius, height) profile listed bottom to top."""
    pts, v = resample(catmull_rom(profile), along)
    tangent = np.gradient(pts, axis=0)
    normal2d = np.stack([tangent[:, 1], -tangent[:, 0]], axis=1)  # outward: (dy, -dr)
    phi = np.linspace(0.0, 2 * np.pi, around + 1)
    cos, sin = np.cos(phi)[None, :], np.sin(phi)[None, :]
    r, y = pts[:, 0:1], pts[:, 1:2]
    pos = np.stack([r * cos, y + 0 * cos, -r * sin], axis=2)
    nr, ny = normal2d[:, 0:1], normal2d[:, 1:2]
    nrm = np.stack([nr * cos, ny + 0 * cos, -nr * sin], axis=2)
    uv = np.stack([np.broadcast_to(phi / (2 * np.pi), pos.shape[:2]),
                   np.broadcast_to(v[:, None], pos.shape[:2])], axis=2)
    mesh.add_grid(pos, nrm, uv)


def tube(mesh, centre, radius, around):
    """A tube along a centre line in the z = 0 plane ((k, 3) points) with radius per point."""
    tangent = np.gradient(centre, axis=0)
    length = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(centre, axis=0), axis=1))])
    tangent /= np.linalg.norm(tangent, axis=1)[:, None]
    binormal = np.array([0.0, 0.0, 1.0])
    side = np.cross(tangent, binormal)
    phi = np.linspace(0.0, 2 * np.pi, around + 1)
    ring = (np.cos(phi)[None, :, None] * side[:, None, :]
            + np.sin(phi)[None, :, None] * binormal[None, None, :])
    pos = centre[:, None, :] + radius[:, None, None] * ring
    # A tapered tube's normal leans back along the centre line by the slope of its radius.
    slope = np.gradient(radius, length)
    nrm = ring - slope[:, None, None] * tangent[:, None, :]
    uv = np.stack([np.broadcast_to(phi[None, :] / (2 * np.pi), pos.shape[:2]),
                   np.broadcast_to((length / length[-1])[:, None], pos.shape[:2])], axis=2)
    mesh.add_grid(pos, nrm, uv)


def spout(mesh):
    """A quadratic Bezier from inside the body's lower side out and up to the tip, tapering from
    radius 0.17 to 0.065 with a slight flare at the tip."""
    t = np.linspace(0.0, 1.0, 49)[:, None]
    p0, p1, p2 = np.array([0.7, 0.3, 0.0]), np.array([1.35, 0.35, 0.0]), np.array([1.6, 0.92, 0.0])
    centre = (1 - t) ** 2 * p0 + 2 * (1 - t) * t * p1 + t**2 * p2
    s = t[:, 0]
    radius = 0.17 - 0.11 * s + 0.012 * np.maximum(0.0, (s - 0.85) / 0.15) ** 2
    tube(mesh, centre, radius, 24)


def handle(mesh):
    """A circular arc behind the body (-x), both ends inside the body, tube radius 0.075."""
    angle = np.radians(np.linspace(48.0, 302.0, 65))
    centre = np.stack([-0.84 + 0.43 * np.cos(angle), 0.52 + 0.43 * np.sin(angle),
                       np.zeros_like(angle)], axis=1)
    tube(mesh, centre, np.full(len(angle), 0.075), 24)


def write_png(path, rgb):
    """An 8-bit RGB PNG of an (h, w, 3) uint8 array, top row first (zlib, no filter)."""
    h, w, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(h))
    chunk = lambda kind, data: (struct.pack(">I", len(data)) + kind + data
                                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"sRGB", b"\x00") + chunk(b"IDAT", zlib.compress(raw, 9))
                + chunk(b"IEND", b""))


def srgb_encode(linear):
    linear = np.asarray(linear, dtype=float)
    return np.where(linear <= 0.0031308, 12.92 * linear, 1.055 * linear ** (1 / 2.4) - 0.055)


def checker(size=256, squares=4, light=(0.8, 0.76, 0.62), dark=(0.08, 0.08, 0.12)):
    cell = (np.arange(size) * squares // size)
    odd = (cell[:, None] + cell[None, :]) % 2 == 1
    colour = np.where(odd[:, :, None], np.array(dark), np.array(light))
    return np.round(255 * srgb_encode(colour)).astype(np.uint8)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=os.path.join(ROOT, "scenes", "kettle"))
    out = parser.parse_args().out
    os.makedirs(out, exist_ok=True)
    mesh = Mesh()
    revolution(mesh, BODY_PROFILE, 128, 80)
    revolution(mesh, KNOB_PROFILE, 48, 16)
    spout(mesh)
    handle(mesh)
    mesh.write_obj(os.path.join(out, "kettle.obj"),
                   ["Kettle for scenes/kettle, written by tools/make_kettle_scene.py: body and",
                    "knob revolved about +y (u around, v along the profile), spout and handle",
                    "tubes (u around, v along); base at y = 0, largest body radius 1.",
                    "%d triangles" % mesh.triangles()])
    write_png(os.path.join(out, "checker.png"), checker())
    print("wrote %s (%d triangles) and checker.png" % (os.path.join(out, "kettle.obj"),
                                                       mesh.triangles()))


if __name__ == "__main__":
    main()
