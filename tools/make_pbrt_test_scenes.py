#!/usr/bin/env python3
"""Writes the pbrt-v4 test scenes of tests/data/pbrt/ (tests/scene/pbrt_test.cpp), from scratch (no
library):

  cornell-box.pbrt   scenes/cornell-box in pbrt-v4's format: the same meshes as "trianglemesh"
                     shapes (quads split 0-1-2, 0-2-3, as the OBJ loader splits them), the same
                     camera (pbrt's left-handed camera space made right-handed by "Scale -1 1 1"
                     before LookAt), diffuse named materials, the light as an "AreaLightSource".
  hierarchy.pbrt     an asymmetric scene with pbrt's plain LookAt (no Scale -1 1 1): nested
                     attributes with Translate, Rotate, Scale, ConcatTransform, Transform and
                     ReverseOrientation, an emissive quad, a coated and a conductor material,
                     an image-mapped texture (checker.png, written here too), a point and a spot
                     light, an object instanced twice, and an Include (hierarchy-lights.pbrt).

usage: tools/make_pbrt_test_scenes.py [OUT_DIR]   (default tests/data/pbrt)
"""
import pathlib
import sys

from make_gltf_test_scenes import png_2x2
from radcache_tools.scene_files import load_json_with_comments, read_obj

ROOT = pathlib.Path(__file__).resolve().parent.parent


def numbers(values):
    return "[ " + " ".join("%.9g" % v for v in values) + " ]"


def mesh(positions, faces, extra=""):
    return ('Shape "trianglemesh"\n    "point3 P" %s\n    "integer indices" %s%s\n'
            % (numbers([c for p in positions for c in p]), numbers([i for f in faces for i in f]), extra))


def cornell_box():
    scene = load_json_with_comments(ROOT / "scenes/cornell-box/scene.json")
    camera = scene["camera"]
    out = ["# scenes/cornell-box/scene.json in pbrt-v4's format (tools/make_pbrt_test_scenes.py)\n",
           "Scale -1 1 1\n",
           "LookAt %s\n" % " ".join("%.9g" % v for v in camera["position"] + camera["look_at"] + camera["up"]),
           'Camera "perspective" "float fov" [ %.9g ]\n' % camera["fov"],
           'Film "rgb" "integer xresolution" [ %d ] "integer yresolution" [ %d ]\n'
           '    "string filename" [ "cornell-box.exr" ]\n' % tuple(camera["resolution"]),
           'Sampler "zsobol" "integer pixelsamples" [ %d ]\n' % scene["render"]["spp"],
           'Integrator "volpath" "integer maxdepth" [ %d ]\n' % scene["render"]["max_depth"],
           'PixelFilter "box"\n',
           "WorldBegin\n"]
    for name, m in scene["materials"].items():
        out.append('MakeNamedMaterial "%s" "string type" [ "diffuse" ] "rgb reflectance" %s\n'
                   % (name, numbers(m["reflectance"])))
    for shape in scene["shapes"]:
        positions, faces = read_obj(ROOT / "scenes/cornell-box" / shape["file"])
        out.append("AttributeBegin  # %s\n" % shape["name"])
        out.append('    NamedMaterial "%s"\n' % shape["material"])
        if "emitter" in shape:
            out.append('    AreaLightSource "diffuse" "rgb L" %s\n' % numbers(shape["emitter"]["radiance"]))
        out.append("    " + mesh(positions, faces))
        out.append("AttributeEnd\n")
    return "".join(out)


QUAD = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
QUAD_FACES = [(0, 1, 2), (0, 2, 3)]


def hierarchy():
    # pbrt's plain LookAt from the origin along +z: pbrt's image has world +x on its right.
    # Film 64 x 32, fov 90 degrees on the shorter (vertical) axis: screen x in [-2, 2],
    # y in [-1, 1]. The lamp's corners (x, y, 0) land at (2 - 0.25 y, 0.5 x, 4): x in
    # [1.75, 2.25], y in [-0.5, 0.5], so it covers pixels x 39-40, y 14-17 exactly.
    return "".join([
        "# An asymmetric pbrt-v4 scene (tools/make_pbrt_test_scenes.py)\n",
        "LookAt 0 0 0  0 0 1  0 1 0\n",
        'Camera "perspective" "float fov" 90\n',
        'Film "rgb" "integer xresolution" 64 "integer yresolution" 32\n',
        'PixelFilter "box"\n',
        'Sampler "independent" "integer pixelsamples" 4\n',
        'Integrator "path" "integer maxdepth" [ 3 ]\n',
        "WorldBegin\n",
        'Texture "checks" "spectrum" "imagemap" "string filename" "checker.png" "float scale" 0.5\n',
        'MakeNamedMaterial "coat" "string type" "coateddiffuse" "rgb reflectance" [0.5 0.25 0.125]\n'
        '    "float roughness" 0.01\n',
        'MakeNamedMaterial "gold" "string type" "conductor" "rgb eta" [0.2 0.4 1.4]\n'
        '    "rgb k" [3.5 2.4 1.8] "float roughness" 0.09 "bool remaproughness" false\n',
        "AttributeBegin  # the lamp\n",
        "    Translate 2 0 4\n",
        "    Rotate 90 0 0 1\n",
        "    Scale 0.5 0.25 1\n",
        "    ReverseOrientation  # its +z winding emits towards -z, the camera\n",
        '    AreaLightSource "diffuse" "rgb L" [ 1 1 1 ]\n',
        "    " + mesh(QUAD, QUAD_FACES),
        "AttributeEnd\n",
        "AttributeBegin  # the plate: ConcatTransform of translate (-2, 0, 6), scale 2\n",
        '    NamedMaterial "gold"\n',
        "    ConcatTransform [ 2 0 0 0  0 2 0 0  0 0 2 0  -2 0 6 1 ]\n",
        "    " + mesh(QUAD, QUAD_FACES),
        "AttributeEnd\n",
        "AttributeBegin  # the picture: Transform replaces the CTM (translate (0, -0.5, 8))\n",
        '    Material "diffuse" "texture reflectance" "checks"\n',
        "    Transform [ 1 0 0 0  0 1 0 0  0 0 1 0  0 -0.5 8 1 ]\n",
        "    " + mesh(QUAD, QUAD_FACES, '\n    "point2 uv" [ 0 0 1 0 1 1 0 1 ]'),
        "AttributeEnd\n",
        'ObjectBegin "tile"\n',
        '    Material "coateddiffuse" "rgb reflectance" [0.2 0.6 0.2]\n',
        "    Scale 0.25 0.25 0.25\n",
        "    " + mesh(QUAD, QUAD_FACES),
        "ObjectEnd\n",
        "AttributeBegin\n    Translate 0 1 5\n    ObjectInstance \"tile\"\nAttributeEnd\n",
        "AttributeBegin\n    Translate 0 -1 5\n    ObjectInstance \"tile\"\nAttributeEnd\n",
        'Include "hierarchy-lights.pbrt"\n',
    ])


def hierarchy_lights():
    return "".join([
        "# Included by hierarchy.pbrt\n",
        "AttributeBegin\n",
        "    Translate 1 2 3\n",
        '    LightSource "point" "rgb I" [ 5 4 3 ] "point3 from" [ 1 0 0 ]\n',
        "AttributeEnd\n",
        'LightSource "spot" "rgb I" [ 20 20 20 ] "float scale" 0.5 "point3 from" [ 0 4 5 ]\n'
        '    "point3 to" [ 0 3 5 ] "float coneangle" 30 "float conedeltaangle" 10\n',
    ])


def main():
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "tests/data/pbrt"
    out.mkdir(parents=True, exist_ok=True)
    (out / "cornell-box.pbrt").write_text(cornell_box())
    (out / "hierarchy.pbrt").write_text(hierarchy())
    (out / "hierarchy-lights.pbrt").write_text(hierarchy_lights())
    (out / "checker.png").write_bytes(png_2x2())


if __name__ == "__main__":
    main()
