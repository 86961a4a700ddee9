#!/usr/bin/env python3
"""Writes the glTF 2.0 test scenes of tests/data/gltf/ (tests/scene/gltf_test.cpp): json with base64
buffers, written from scratch (no library):

  cornell-box.gltf   scenes/cornell-box as glTF: the same meshes (quads split 0-1-2, 0-2-3), the
                     same camera (a node turned 180 degrees about y), diffuse materials as
                     metallic 0 / roughness 1, the light as an emissive material with
                     KHR_materials_emissive_strength.
  hierarchy.gltf     an asymmetric scene: a node hierarchy (translation, rotation, scale, matrix)
                     holding an emissive quad, a glossy metal, a textured quad (embedded PNG),
                     a thin-walled glass window (KHR_materials_transmission) and a solid rough
                     glass block (with KHR_materials_volume and KHR_materials_ior), a point
                     light and a spot light, and two cameras.

usage: tools/make_gltf_test_scenes.py [OUT_DIR]   (default tests/data/gltf)
"""
import base64
import json
import math
import pathlib
import struct
import sys
import zlib

from radcache_tools.scene_files import load_json_with_comments, read_obj

ROOT = pathlib.Path(__file__).resolve().parent.parent


class Builder:
    def __init__(self):
        self.data = bytearray()
        self.gltf = {"asset": {"version": "2.0", "generator": "radcache tools/make_gltf_test_scenes.py"},
                     "buffers": [], "bufferViews": [], "accessors": [], "meshes": [],
                     "nodes": [], "materials": [], "scenes": [{"nodes": []}], "scene": 0}

    def view(self, payload):
        while len(self.data) % 4:
            self.data.append(0)
        self.gltf["bufferViews"].append({"buffer": 0, "byteOffset": len(self.data),
                                         "byteLength": len(payload)})
        self.data += payload
        return len(self.gltf["bufferViews"]) - 1

    def accessor(self, values, kind, component):
        width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3}[kind]
        fmt = "<%d%s" % (len(values), "f" if component == 5126 else "I")
        view = self.view(struct.pack(fmt, *values))
        acc = {"bufferView": view, "componentType": component, "count": len(values) // width,
               "type": kind}
        if kind == "VEC3" and component == 5126:
            acc["min"] = [min(values[i::3]) for i in range(3)]
            acc["max"] = [max(values[i::3]) for i in range(3)]
        self.gltf["accessors"].append(acc)
        return len(self.gltf["accessors"]) - 1

    def mesh(self, positions, triangles, material, uvs=None):
        attributes = {"POSITION": self.accessor([c for p in positions for c in p], "VEC3", 5126)}
        if uvs:
            attributes["TEXCOORD_0"] = self.accessor([c for t in uvs for c in t], "VEC2", 5126)
        indices = self.accessor([i for t in triangles for i in t], "SCALAR", 5125)
        self.gltf["meshes"].append({"primitives": [{"attributes": attributes, "indices": indices,
                                                     "material": material}]})
        return len(self.gltf["meshes"]) - 1

    def material(self, **fields):
        self.gltf["materials"].append(fields)
        return len(self.gltf["materials"]) - 1

    def node(self, root=True, **fields):
        self.gltf["nodes"].append(fields)
        index = len(self.gltf["nodes"]) - 1
        if root:
            self.gltf["scenes"][0]["nodes"].append(index)
        return index

    def finish(self):
        self.gltf["buffers"] = [{"byteLength": len(self.data), "uri": "data:application/octet-stream;base64,"
                                 + base64.b64encode(bytes(self.data)).decode()}]
        return json.dumps(self.gltf, indent=1)


def cornell_box():
    scene = load_json_with_comments(ROOT / "scenes/cornell-box/scene.json")
    b = Builder()
    materials = {}
    for name, m in scene["materials"].items():
        materials[name] = b.material(name=name, pbrMetallicRoughness={
            "baseColorFactor": m["reflectance"] + [1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0})
    b.gltf["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    for shape in scene["shapes"]:
        positions, faces = read_obj(ROOT / "scenes/cornell-box" / shape["file"])
        material = materials[shape["material"]]
        if "emitter" in shape:
            radiance = shape["emitter"]["radiance"]
            peak = max(radiance)
            material = b.material(name="light", pbrMetallicRoughness={
                "baseColorFactor": scene["materials"]["light"]["reflectance"] + [1.0],
                "metallicFactor": 0.0, "roughnessFactor": 1.0},
                emissiveFactor=[r / peak for r in radiance],
                extensions={"KHR_materials_emissive_strength": {"emissiveStrength": peak}})
        b.node(name=shape["name"], mesh=b.mesh(positions, faces, material))
    camera = scene["camera"]
    fov = math.radians(camera["fov"])  # square image: the x and y fields of view agree
    b.gltf["cameras"] = [{"name": "main", "type": "perspective",
                          "perspective": {"yfov": fov, "aspectRatio": 1.0, "znear": 1.0}}]
    b.node(name="camera", camera=0, translation=camera["position"], rotation=[0.0, 1.0, 0.0, 0.0])
    return b.finish()


def png_2x2():
    """A 2x2 RGB PNG: red, green / blue, white (rows top to bottom)."""
    rows = [bytes([0, 255, 0, 0, 0, 255, 0]), bytes([0, 0, 0, 255, 255, 255, 255])]
    def chunk(kind, payload):
        return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(b"".join(rows))) + chunk(b"IEND", b""))


def hierarchy():
    b = Builder()
    quad = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
    quad_faces = [(0, 1, 2), (0, 2, 3)]
    quad_uvs = [(0, 1), (1, 1), (1, 0), (0, 0)]
    emissive = b.material(name="lamp", emissiveFactor=[1.0, 0.5, 0.25],
                          pbrMetallicRoughness={"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0.0})
    metal = b.material(name="gold", pbrMetallicRoughness={"baseColorFactor": [0.9, 0.6, 0.2, 1],
                                                          "metallicFactor": 1.0, "roughnessFactor": 0.3})
    floor = b.material(name="floor", pbrMetallicRoughness={"baseColorFactor": [0.8, 0.8, 0.8, 1],
                                                           "metallicFactor": 0.0, "roughnessFactor": 0.9})
    textured = b.material(name="checker", pbrMetallicRoughness={
        "baseColorTexture": {"index": 0}, "baseColorFactor": [0.5, 1, 1, 1], "metallicFactor": 0.0})
    window = b.material(name="window", pbrMetallicRoughness={"metallicFactor": 0.0},
                        extensions={"KHR_materials_transmission": {"transmissionFactor": 1.0}})
    lens = b.material(name="lens", pbrMetallicRoughness={"metallicFactor": 0.0,
                                                         "roughnessFactor": 0.2},
                      extensions={"KHR_materials_transmission": {"transmissionFactor": 0.9},
                                  "KHR_materials_ior": {"ior": 1.33},
                                  "KHR_materials_volume": {"thicknessFactor": 0.1}})
    view = b.view(png_2x2())
    b.gltf["images"] = [{"bufferView": view, "mimeType": "image/png"}]
    b.gltf["textures"] = [{"source": 0}]
    lamp = b.mesh(quad, quad_faces, emissive)
    plate = b.mesh(quad, quad_faces, metal)
    ground = b.mesh(quad, quad_faces, floor)
    picture = b.mesh(quad, quad_faces, textured, quad_uvs)
    # parent: translate (1, 2, 3), rotate 90 degrees about z; child: scale (0.5, 0.25, 1) -> the
    # lamp's corners land at (1 - 0.25 y, 2 + 0.5 x, 3).
    child = b.node(root=False, name="lamp", mesh=lamp, scale=[0.5, 0.25, 1.0])
    s = math.sqrt(0.5)
    b.node(name="arm", translation=[1.0, 2.0, 3.0], rotation=[0.0, 0.0, s, s], children=[child])
    # column-major matrix: translate (-2, 0, 1), scale 2.
    b.node(name="plate", mesh=plate, matrix=[2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, -2, 0, 1, 1])
    b.node(name="ground", mesh=ground, translation=[0, -1, 0], rotation=[-s, 0, 0, s],
           scale=[5, 5, 5])
    b.node(name="picture", mesh=picture, translation=[2.5, 0.5, -1.0])
    b.node(name="window", mesh=b.mesh(quad, quad_faces, window), translation=[-3.0, 0.5, -2.0])
    b.node(name="lens", mesh=b.mesh(quad, quad_faces, lens), translation=[3.0, 0.5, -2.0])
    b.gltf["extensionsUsed"] = ["KHR_lights_punctual", "KHR_materials_transmission",
                                "KHR_materials_ior", "KHR_materials_volume"]
    b.gltf["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "point", "color": [1, 0.8, 0.6], "intensity": 5.0},
        {"type": "spot", "intensity": 20.0, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}},
        {"type": "directional", "color": [1, 1, 0.5], "intensity": 0.5}]}}
    b.node(name="bulb", translation=[0, 3, 2], extensions={"KHR_lights_punctual": {"light": 0}})
    # The spot at (0, 4, 0) pointing down (-z turned to -y: 90 degrees about x).
    b.node(name="spot", translation=[0, 4, 0], rotation=[-s, 0, 0, s],
           extensions={"KHR_lights_punctual": {"light": 1}})
    # The sun travelling along -x (-z turned 90 degrees about y).
    b.node(name="sun", rotation=[0, s, 0, s], extensions={"KHR_lights_punctual": {"light": 2}})
    b.gltf["cameras"] = [{"name": "front", "type": "perspective", "perspective": {"yfov": 0.8, "aspectRatio": 1.5, "znear": 0.1}},
                         {"name": "side", "type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.1}}]
    b.node(name="front_node", camera=0, translation=[0, 1, 10])
    b.node(name="side_node", camera=1, translation=[10, 1, 0], rotation=[0, s, 0, s])
    return b.finish()


def main():
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "tests/data/gltf"
    out.mkdir(parents=True, exist_ok=True)
    (out / "cornell-box.gltf").write_text(cornell_box() + "\n")
    (out / "hierarchy.gltf").write_text(hierarchy() + "\n")


if __name__ == "__main__":
    main()
