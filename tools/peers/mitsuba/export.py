"""A radcache scene as a Mitsuba 3 scene dictionary (for mi.load_dict): what the Mitsuba peer
renders (a library, not a command; tools/peers/mitsuba/render.py is the command).

Only what has an exact counterpart in Mitsuba 3 is exported; anything else raises ExportError
with one line naming it. The mapping (docs/peers.md):

  camera      pinhole `perspective`, the same fov and fov_axis, to_world = look_at(position,
              look_at, up) (image x along cross(forward, up) in both renderers)
  filter      box (radius 0.5: Mitsuba's `box`) or tent (`tent`, the same radius); radcache's
              Gaussian (sigma = R/3, cut at R) differs from Mitsuba's (cut at 4 sigma): refused
  diffuse     `twosided` `diffuse` (radcache's materials are two-sided, Mitsuba's one-sided)
  conductor   `twosided` `conductor` (alpha 0) or `roughconductor` (GGX, alpha_u = alpha_x,
              alpha_v = alpha_y) with the same eta and k; a reflectance r as eta 1 and
              k = 2 sqrt(r / (1 - r)), as radcache converts it
  dielectric  `dielectric` (alpha 0) or `roughdielectric` (GGX) with int_ior = ior, ext_ior 1
              (both renderers put the index on the side the normal points away from)
  thindielectric   `thindielectric`, int_ior = ior
  phong, ward refused: Mitsuba 3 has neither the modified Phong nor the bounded-albedo Ward
  textures    refused (the uv and colour conventions of Mitsuba's `bitmap` are unchecked)
  obj         `obj` with face_normals unless every face has vertex normals (Mitsuba would smooth
              the normals of a mesh without them); MTL materials refused
  rectangle, cube   Mitsuba's, which are the same shapes ([-1, 1]^2 facing +z, [-1, 1]^3)
  sphere      Mitsuba's exact sphere (radcache tessellates 48 x 96 quads: a slightly smaller,
              faceted surface with smooth normals, not the same geometry)
  area light  `area` with the same radiance, emitting on the front side; a mirroring transform of
              an emitter is refused
  point, spot, constant   Mitsuba's `point`, `spot` (the same linear fall-off), `constant`
  distant     Mitsuba's `directional` (the same direction of travel and irradiance)
  envmap      Mitsuba's `envmap` (the same lat-long convention) of the image with each texel
              repeated 8 x 8, so that its bilinear lookup matches radcache's constant texels but
              within 1/16 texel of their edges; an equal-area map or a scale per channel refused
  depth       path `max_depth` = radcache's max_depth + 1 (Mitsuba counts the camera segment),
              rr_depth likewise (Russian roulette changes the noise, not the mean)
  animation   refused (the peer renders still scenes)
"""

import math
import os

import numpy

from radcache_tools.scene_files import load_json_with_comments

RENDER_DEFAULTS = {"spp": 16, "max_depth": 64, "rr_depth": 3}


class ExportError(Exception):
    """What a scene has that the peer cannot render exactly: one line."""


def colour(value, default):
    """A radcache colour (number or [r, g, b]) as Mitsuba's rgb."""
    value = default if value is None else value
    rgb = [float(value)] * 3 if isinstance(value, (int, float)) else [float(v) for v in value]
    return {"type": "rgb", "value": rgb}


def rotation(axis, degrees):
    """Right-handed rotation about an axis (Rodrigues), 4x4."""
    a = numpy.asarray(axis, dtype=float)
    x, y, z = a / numpy.linalg.norm(a)
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    m = numpy.identity(4)
    m[:3, :3] = [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
                 [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
                 [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]]
    return m


def step_matrix(step):
    m = numpy.identity(4)
    if "translate" in step:
        m[:3, 3] = step["translate"]
    elif "scale" in step:
        s = step["scale"]
        m[:3, :3] = numpy.diag([s] * 3 if isinstance(s, (int, float)) else s)
    elif "rotate" in step:
        m = rotation(step["rotate"]["axis"], step["rotate"]["angle"])
    elif "matrix" in step:
        m = numpy.asarray(step["matrix"], dtype=float).reshape(4, 4)
    return m


def transform(steps):
    """A radcache transform (steps applied in the listed order) as one 4x4 matrix."""
    m = numpy.identity(4)
    for step in steps or []:
        m = step_matrix(step) @ m
    return m


def conductor_eta_k(spec):
    """A radcache conductor's (eta, k) per channel: given, or pbrt-v4's form of a reflectance."""
    if "reflectance" in spec:
        r = numpy.clip(numpy.array(colour(spec["reflectance"], 1)["value"]), 0.0, 0.9999)
        return colour(1, 1), colour([float(v) for v in 2.0 * numpy.sqrt(r / (1.0 - r))], 0)
    return colour(spec["eta"], 1), colour(spec["k"], 0)


def alphas(spec):
    alpha = spec.get("alpha", 0.0)
    return spec.get("alpha_x", alpha), spec.get("alpha_y", alpha)


def conductor(spec):
    eta, k = conductor_eta_k(spec)
    alpha_x, alpha_y = alphas(spec)
    bsdf = {"type": "conductor", "eta": eta, "k": k}
    if max(alpha_x, alpha_y) >= 1e-3:  # radcache renders alphas below 1e-3 smooth
        bsdf.update({"type": "roughconductor", "distribution": "ggx",
                     "alpha_u": float(alpha_x), "alpha_v": float(alpha_y)})
    return {"type": "twosided", "bsdf": bsdf}


def dielectric(spec, thin):
    ior = float(spec.get("ior", 1.5))
    if thin:
        return {"type": "thindielectric", "int_ior": ior, "ext_ior": 1.0}
    alpha_x, alpha_y = alphas(spec)
    bsdf = {"type": "dielectric", "int_ior": ior, "ext_ior": 1.0}
    if max(alpha_x, alpha_y) >= 1e-3 and ior != 1.0:
        bsdf.update({"type": "roughdielectric", "distribution": "ggx",
                     "alpha_u": float(alpha_x), "alpha_v": float(alpha_y)})
    return bsdf


def material(name, spec):
    """A named radcache material as a Mitsuba BSDF, or ExportError naming it."""
    kind = spec.get("type", "diffuse")
    if kind == "conductor":
        return conductor(spec)
    if kind in ("dielectric", "thindielectric"):
        return dielectric(spec, kind == "thindielectric")
    if kind != "diffuse":
        raise ExportError("material '%s' (%s): Mitsuba 3 has no exact counterpart; not exported"
                          % (name, kind))
    reflectance = spec.get("reflectance")
    if isinstance(reflectance, dict):
        raise ExportError("material '%s': textures are not exported" % name)
    return {"type": "twosided",
            "bsdf": {"type": "diffuse", "reflectance": colour(reflectance, 0.5)}}


def obj_has_normals(path):
    """Whether every face of an OBJ file names a vertex normal (radcache uses them only then)."""
    faces = with_normals = 0
    with open(path) as f:
        for line in f:
            if line.startswith("f "):
                faces += 1
                with_normals += all(c.count("/") == 2 and not c.endswith("/")
                                    for c in line.split()[1:])
    return faces > 0 and faces == with_normals


def shape(spec, index, folder, bsdfs):
    """One radcache shape as a Mitsuba shape."""
    import mitsuba as mi
    name = spec.get("name", "%s_%d" % (spec["type"], index))
    to_world = transform(spec.get("transform"))
    kind = spec["type"]
    out = {}
    if kind == "obj":
        if "material" not in spec:
            raise ExportError("shape '%s': materials from an MTL library are not exported" % name)
        path = os.path.join(folder, spec["file"])
        out = {"type": "obj", "filename": path, "face_normals": not obj_has_normals(path)}
    elif kind in ("rectangle", "cube"):
        out = {"type": kind}
    elif kind == "sphere":
        centre = spec.get("center", [0, 0, 0])
        to_world = to_world @ step_matrix({"translate": centre}) @ step_matrix(
            {"scale": spec.get("radius", 1)})
        out = {"type": "sphere"}
    else:
        raise ExportError("shape '%s': type %s is not exported" % (name, kind))
    out["to_world"] = mi.ScalarTransform4f(to_world.tolist())
    out["flip_normals"] = bool(spec.get("flip_normals", False))
    out["bsdf"] = {"type": "ref", "id": "material-" + spec.get("material", "default")}
    if spec.get("material", "default") not in bsdfs:
        raise ExportError("shape '%s': unknown material '%s'" % (name, spec["material"]))
    emitter = spec.get("emitter")
    if emitter:
        if numpy.linalg.det(to_world[:3, :3]) < 0:
            raise ExportError("shape '%s': a mirrored emitter is not exported" % name)
        out["emitter"] = {"type": "area", "radiance": colour(emitter.get("radiance"), 1)}
    return name, out


def nearest_envmap(path, factor=8):
    """radcache reads an envmap's texels as constant over their area, Mitsuba's envmap
    interpolates bilinearly: the image with every texel repeated factor x factor (written beside
    the original as NAME.nearestK.exr) makes the interpolation differ only within 1/2K of a texel
    of its edges."""
    import mitsuba as mi
    import numpy
    out = "%s.nearest%d.exr" % (os.path.splitext(path)[0], factor)
    image = numpy.array(mi.Bitmap(path).convert(mi.Bitmap.PixelFormat.RGB,
                                                mi.Struct.Type.Float32, srgb_gamma=False))
    repeated = numpy.repeat(numpy.repeat(image, factor, axis=0), factor, axis=1)
    mi.Bitmap(numpy.ascontiguousarray(repeated)).write(out)
    return out


def emitter(spec, index, folder):
    """A point, spot, distant or constant radcache emitter as Mitsuba's."""
    import mitsuba as mi
    kind = spec["type"]
    if kind == "point":
        return {"type": "point", "position": list(map(float, spec["position"])),
                "intensity": colour(spec.get("intensity"), 1)}
    if kind == "constant":
        return {"type": "constant", "radiance": colour(spec.get("radiance"), 1)}
    if kind == "envmap":
        if spec.get("mapping", "latlong") != "latlong":
            raise ExportError("emitter %d: an %s envmap has no Mitsuba counterpart"
                              % (index, spec["mapping"]))
        scale = spec.get("scale", 1)
        if isinstance(scale, list):
            if len(set(map(float, scale))) != 1:
                raise ExportError("emitter %d: an envmap scale per channel is not exported" % index)
            scale = scale[0]
        return {"type": "envmap", "filename": nearest_envmap(os.path.join(folder, spec["filename"])),
                "scale": float(scale)}
    if kind == "distant":
        return {"type": "directional", "direction": list(map(float, spec["direction"])),
                "irradiance": colour(spec.get("irradiance"), 1)}
    if kind == "spot":
        cutoff = float(spec.get("cutoff_angle", 20))
        direction = numpy.subtract(spec["look_at"], spec["position"])
        up = [0, 1, 0] if abs(direction[1]) < 0.9 * numpy.linalg.norm(direction) else [1, 0, 0]
        return {"type": "spot", "intensity": colour(spec.get("intensity"), 1),
                "cutoff_angle": cutoff, "beam_width": float(spec.get("beam_width", 0.75 * cutoff)),
                "to_world": mi.ScalarTransform4f().look_at(
                    origin=spec["position"], target=spec["look_at"], up=up)}
    raise ExportError("emitter %d: type %s is not exported" % (index, kind))


def rfilter(camera):
    spec = camera.get("filter", {"type": "box"})
    kind = spec.get("type", "box")
    if kind == "box" and spec.get("radius", 0.5) == 0.5:
        return {"type": "box"}
    if kind == "tent":
        return {"type": "tent", "radius": float(spec.get("radius", 1.0))}
    raise ExportError("camera filter %s (radius %s): Mitsuba 3 has no exact counterpart; "
                      "not exported" % (kind, spec.get("radius", "default")))


def sensor(camera, width, height, spp):
    import mitsuba as mi
    resolution = camera.get("resolution", [512, 512])
    return {"type": "perspective", "fov": float(camera["fov"]),
            "fov_axis": camera.get("fov_axis", "x"), "near_clip": 1e-4, "far_clip": 1e9,
            "to_world": mi.ScalarTransform4f().look_at(
                origin=camera["position"], target=camera["look_at"],
                up=camera.get("up", [0, 1, 0])),
            "sampler": {"type": "independent", "sample_count": spp},
            "film": {"type": "hdrfilm", "width": width or resolution[0],
                     "height": height or resolution[1], "pixel_format": "rgb",
                     "rfilter": rfilter(camera)}}


def scene_dict(scene_json, width=None, height=None, spp=None, integrator=None):
    """The Mitsuba scene of a radcache scene.json (the caller has imported mitsuba and set its
    variant). integrator: a Mitsuba integrator dict (default: `path` with the scene's depth
    settings). Raises ExportError naming what is not exported."""
    scene = load_json_with_comments(scene_json)
    folder = os.path.dirname(os.path.abspath(scene_json))
    render = dict(RENDER_DEFAULTS, **scene.get("render", {}))
    bsdfs = {"default": {"type": "twosided", "bsdf": {"type": "diffuse"}}}
    for name, spec in scene.get("materials", {}).items():
        bsdfs[name] = material(name, spec)
    if scene.get("animation", {}).get("tracks"):
        raise ExportError("animation tracks are not exported (the peer renders still scenes)")
    out = {"type": "scene",
           "integrator": integrator or {"type": "path", "max_depth": render["max_depth"] + 1,
                                        "rr_depth": render["rr_depth"] + 1},
           "sensor": sensor(scene["camera"], width, height, spp or render["spp"])}
    for name, bsdf in bsdfs.items():
        out["material-" + name] = dict(bsdf, id="material-" + name)
    for index, spec in enumerate(scene["shapes"]):
        name, value = shape(spec, index, folder, bsdfs)
        out["shape-" + name] = value
    for index, spec in enumerate(scene.get("emitters", [])):
        out["emitter-%d" % index] = emitter(spec, index, folder)
    return out
