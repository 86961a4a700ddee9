"""A scene's source files as the scene-writing tools read them: scene.json (JSON with // comment
lines) and the Wavefront OBJ meshes it names. Python 3 standard library only."""

import json


def load_json_with_comments(path):
    """The JSON of `path` without its // comment lines."""
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
