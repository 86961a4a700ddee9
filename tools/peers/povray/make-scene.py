#!/usr/bin/env python3
"""Writes tools/peers/povray/cornell-box.pov, the POV-Ray 3.7 peer of scenes/cornell-box.

Reads scenes/cornell-box/scene.json (JSON with // comment lines) and the OBJ files it names, and
writes every triangle with its exact vertex coordinates (millimetres) into one POV-Ray `mesh` per
shape, with the shape's Lambertian reflectance as pigment. Lighting is radiosity only (POV-Ray's
irradiance cache, Ward et al. 1988): no light_source; the emitter gets `emission` such that the
surface emits exactly the scene's radiance (POV-Ray multiplies emission by the pigment), and it
keeps its own diffuse reflectance as in radcache. Physics of the mapping:

  * POV-Ray radiosity returns the mean radiance over cosine-distributed directions, E / pi, and a
    surface adds pigment * diffuse * that = rho E / pi, the Lambertian outgoing radiance: so
    `diffuse 1`, `brilliance 1`, radiosity `brightness 1`, `gray_threshold 0`, `ambient 0`.
  * A ray reaching a surface picks up pigment * emission; with pigment rho and emission L / rho the
    surface emits L, seen directly and by radiosity rays alike.
  * POV-Ray's y is up, z forward, x right, left-handed; radcache's world is right-handed with the
    same axes, so the camera gets `right -x` (x grows to the left of the image, as in radcache).

Quality settings are left to `#declare`s with defaults (RadCount, RadNearest, RadErrorBound,
RadLowError, RadPretraceEnd, RadRecursion) that the command line can override with
`Declare=NAME=VALUE` (see run.sh). Python 3 standard library only.

Usage: tools/peers/povray/make-scene.py [--scene DIR] [-o FILE]
"""

import argparse
import json
import math
import os

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))


def load_json_with_comments(path):
    with open(path) as f:
        lines = [line for line in f if not line.lstrip().startswith("//")]
    return json.loads("".join(lines))


def read_obj(path):
    """Vertices and triangles (fans of polygons) of a Wavefront OBJ file."""
    vertices, triangles = [], []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if not fields:
                continue
            if fields[0] == "v":
                vertices.append(tuple(float(x) for x in fields[1:4]))
            elif fields[0] == "f":
                index = []
                for field in fields[1:]:
                    i = int(field.split("/")[0])
                    index.append(i - 1 if i > 0 else len(vertices) + i)
                for k in range(1, len(index) - 1):
                    triangles.append((index[0], index[k], index[k + 1]))
    return vertices, triangles


def fmt(x):
    """Shortest exact decimal of x ("549.6", "0", "21.794871794871796")."""
    s = repr(float(x))
    return s[:-2] if s.endswith(".0") else s


def vec(v):
    return "<" + ", ".join(fmt(x) for x in v) + ">"


def camera_block(camera):
    position, look_at, up = camera["position"], camera["look_at"], camera["up"]
    width, height = camera["resolution"]
    if camera.get("fov_axis", "x") != "x":
        raise SystemExit("only fov_axis x is supported")
    # POV-Ray's `angle` is the horizontal field of view across the `right` vector; `right -x`
    # (length width/height) turns POV-Ray's left-handed image into radcache's right-handed one.
    return f"""camera {{
    perspective
    location {vec(position)}
    direction z
    up y
    right -x * {fmt(width / height)}
    sky {vec(up)}
    angle {fmt(camera["fov"])}
    look_at {vec(look_at)}
}}
"""


def texture_block(material, emitter):
    if material["type"] != "diffuse":
        raise SystemExit(f"material type {material['type']} has no POV-Ray mapping here")
    rho = material["reflectance"]
    emission = [0.0, 0.0, 0.0]
    if emitter is not None:
        if emitter["type"] != "area":
            raise SystemExit(f"emitter type {emitter['type']} has no POV-Ray mapping here")
        # POV-Ray adds pigment * emission: divide by the pigment so the surface emits L.
        emission = [L / r for L, r in zip(emitter["radiance"], rho)]
    return (f"texture {{ pigment {{ rgb {vec(rho)} }}\n"
            f"        finish {{ ambient 0 emission rgb {vec(emission)} diffuse 1 brilliance 1"
            f" specular 0 phong 0 reflection 0 }} }}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scene", default=os.path.join(ROOT, "scenes", "cornell-box"))
    parser.add_argument("-o", "--output",
                        default=os.path.join(ROOT, "tools", "peers", "povray", "cornell-box.pov"))
    args = parser.parse_args()

    scene = load_json_with_comments(os.path.join(args.scene, "scene.json"))
    camera = scene["camera"]
    out = []
    radiance = [s["emitter"]["radiance"] for s in scene["shapes"] if "emitter" in s]
    out.append(f"""// Cornell box (scenes/cornell-box) for POV-Ray 3.7: radiosity-only peer of radcache.
// Generated by tools/peers/povray/make-scene.py from scene.json and the OBJ meshes; do not edit.
// Millimetres; triangles with the exact vertex coordinates of the OBJ files. Lambertian surfaces
// (pigment = reflectance, diffuse 1); emitters of radiance {", ".join(vec(L) for L in radiance)}
// by `emission` (pigment * emission = radiance), no light_source. Linear: assumed_gamma 1, write
// OpenEXR or Radiance HDR (+FE / +FH). Quality: override the declares below with Declare=NAME=VALUE.
#version 3.7;

#ifndef (RadCount)       #declare RadCount = 400;         #end
#ifndef (RadNearest)     #declare RadNearest = 10;        #end
#ifndef (RadErrorBound)  #declare RadErrorBound = 0.5;    #end
#ifndef (RadLowError)    #declare RadLowError = 0.5;      #end
#ifndef (RadPretraceEnd) #declare RadPretraceEnd = 0.01;  #end
#ifndef (RadRecursion)   #declare RadRecursion = 10;      #end

global_settings {{
    assumed_gamma 1.0
    max_trace_level 64
    adc_bailout 0.0001
    ambient_light rgb 0
    radiosity {{
        count RadCount
        nearest_count RadNearest
        error_bound RadErrorBound
        low_error_factor RadLowError
        recursion_limit RadRecursion
        pretrace_start 0.08
        pretrace_end RadPretraceEnd
        minimum_reuse 0.015
        maximum_reuse 0.2
        brightness 1
        gray_threshold 0
        adc_bailout 0.0001
        always_sample off
        normal off
        media off
        subsurface off
    }}
}}

background {{ rgb 0 }}

""")
    out.append(camera_block(camera))
    materials = scene["materials"]
    for shape in scene["shapes"]:
        if shape["type"] != "obj":
            raise SystemExit(f"shape type {shape['type']} has no POV-Ray mapping here")
        vertices, triangles = read_obj(os.path.join(args.scene, shape["file"]))
        out.append(f"\n// {shape['name']}: {shape['file']}, material {shape['material']}\n")
        out.append("mesh {\n")
        for a, b, c in triangles:
            out.append(f"    triangle {{ {vec(vertices[a])}, {vec(vertices[b])}, {vec(vertices[c])} }}\n")
        out.append("    " + texture_block(materials[shape["material"]], shape.get("emitter")) + "\n")
        out.append("}\n")
    with open(args.output, "w") as f:
        f.write("".join(out))
    print(f"wrote {os.path.relpath(args.output)}")


if __name__ == "__main__":
    main()
