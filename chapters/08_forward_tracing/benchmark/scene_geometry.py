"""The geometry of a course scene (assets/scenes/*.json) in plain Python, shared by chapter 08's benchmark scripts.

Vectors are tuples of three numbers. This module holds what the scripts must compute exactly as the course
does: the shape transform, a box's six faces, a mesh file's triangles, the pinhole camera and a ray's first hit
on a quad or a sphere.
Only Python's standard library is used, so it imports both in the system's Python (against_cycles.py,
analytic_check.py) and in Blender's bundled one (cycles_scene.py).
"""
import math
import os
import struct

# --- vectors ---------------------------------------------------------------------------------------------

def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def normalize(a): return mul(a, 1 / math.sqrt(dot(a, a)))


# --- shapes ----------------------------------------------------------------------------------------------

def transform_point(t, p):
    """The course's transform `t`: scale, rotate_x, rotate_y, rotate_z, translate (right-handed, degrees)."""
    x, y, z = p
    s = t.get("scale", 1)
    sx, sy, sz = (s, s, s) if isinstance(s, (int, float)) else s
    x, y, z = x * sx, y * sy, z * sz
    a = math.radians(t.get("rotate_x", 0))
    y, z = y * math.cos(a) - z * math.sin(a), y * math.sin(a) + z * math.cos(a)
    a = math.radians(t.get("rotate_y", 0))
    x, z = x * math.cos(a) + z * math.sin(a), -x * math.sin(a) + z * math.cos(a)
    a = math.radians(t.get("rotate_z", 0))
    x, y = x * math.cos(a) - y * math.sin(a), x * math.sin(a) + y * math.cos(a)
    tx, ty, tz = t.get("translate", [0, 0, 0])
    return (x + tx, y + ty, z + tz)


def quad_corners(quad):
    """A quad (origin, u, v)'s four corners, counter-clockwise seen from u x v (the side its normal faces)."""
    origin, u, v = quad
    return [origin, add(origin, u), add(add(origin, u), v), add(origin, v)]


def box_quads(box):
    """A box shape's six faces as quads (origin, u, v) with u x v pointing outward (as the course builds them),
    each moved by the box's transform: its origin, origin + u and origin + v are transformed."""
    lo, hi = box["min"], box["max"]
    t = box.get("transform", {})
    dx, dy, dz = hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]
    X, Y, Z = (dx, 0, 0), (0, dy, 0), (0, 0, dz)
    neg = lambda v: (-v[0], -v[1], -v[2])
    faces = [
        ((lo[0], lo[1], hi[2]), X, Y),           # front  z = max, normal +z
        ((hi[0], lo[1], lo[2]), neg(X), Y),      # back   z = min, normal -z
        ((hi[0], lo[1], hi[2]), neg(Z), Y),      # right  x = max, normal +x
        ((lo[0], lo[1], lo[2]), Z, Y),           # left   x = min, normal -x
        ((lo[0], hi[1], hi[2]), X, neg(Z)),      # top    y = max, normal +y
        ((lo[0], lo[1], lo[2]), X, Z),           # bottom y = min, normal -y
    ]
    quads = []
    for origin, u, v in faces:
        p0 = transform_point(t, origin)
        pu = transform_point(t, add(origin, u))
        pv = transform_point(t, add(origin, v))
        quads.append((p0, sub(pu, p0), sub(pv, p0)))
    return quads


def mesh_triangles(mesh, scene_folder):
    """A mesh shape's triangles [(p0, p1, p2)] after its transform, read from its OBJ or PLY file (relative to
    the scene's folder) as the course reads it: polygons split into fans (0, k, k + 1). Raises ValueError for a
    file with vertex normals, which the course shades smooth (the translations here are faceted only)."""
    path = os.path.join(scene_folder, mesh["file"])
    with open(path, "rb") as f:
        data = f.read()
    positions, polygons, has_normals = (read_ply if path.lower().endswith(".ply") else read_obj)(data)
    if has_normals:
        raise ValueError("%s: a mesh with vertex normals is shaded smooth by the course; not translated" % path)
    t = mesh.get("transform", {})
    points = [transform_point(t, p) for p in positions]
    return [(points[poly[0]], points[poly[k]], points[poly[k + 1]])
            for poly in polygons for k in range(1, len(poly) - 1)]


def read_obj(data):
    """(positions, polygons as 0-based index lists, whether it has vn lines) of an OBJ file's text."""
    positions, polygons, has_normals = [], [], False
    for line in data.decode("utf-8").splitlines():
        fields = line.split()
        if not fields:
            continue
        if fields[0] == "v":
            positions.append(tuple(float(x) for x in fields[1:4]))
        elif fields[0] == "vn":
            has_normals = True
        elif fields[0] == "f":
            idx = [int(v.split("/")[0]) for v in fields[1:]]
            polygons.append([i - 1 if i > 0 else len(positions) + i for i in idx])
    return positions, polygons, has_normals


PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h", "ushort": "H",
             "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I", "float": "f", "float32": "f",
             "double": "d", "float64": "d"}


def read_ply(data):
    """(positions, polygons, whether its vertices have nx) of an ASCII or binary PLY file."""
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii").splitlines()
    fmt = header[1].split()[1]
    elements = []  # [name, count, [(property name, type, list count type or None)]]
    for line in header:
        f = line.split()
        if f and f[0] == "element":
            elements.append([f[1], int(f[2]), []])
        elif f and f[0] == "property":
            elements[-1][2].append((f[-1], f[2], f[3]) if f[1] == "list" else (f[-1], f[1], None))
    body = data[end:]
    if fmt == "ascii":
        tokens = body.split()
        pos = 0

        def take(kind):
            nonlocal pos
            pos += 1
            return (float if PLY_TYPES[kind] in "fd" else int)(tokens[pos - 1])
    else:
        order = "<" if fmt == "binary_little_endian" else ">"
        pos = 0

        def take(kind):
            nonlocal pos
            code = order + PLY_TYPES[kind]
            value = struct.unpack_from(code, body, pos)[0]
            pos += struct.calcsize(code)
            return value
    positions, polygons, has_normals = [], [], False
    for name, count, props in elements:
        for _ in range(count):
            row = {}
            for prop, kind, item in props:
                row[prop] = [take(item) for _ in range(take(kind))] if item else take(kind)
            if name == "vertex":
                positions.append((row["x"], row["y"], row["z"]))
                has_normals = has_normals or "nx" in row
            elif name == "face":
                polygons.append(row.get("vertex_indices", row.get("vertex_index")))
    return positions, polygons, has_normals


# --- the camera ------------------------------------------------------------------------------------------

def camera_basis(camera):
    """(eye, forward, right, up) of a scene's "camera" (from, at, up): right = forward x up, up' = right x
    forward, all unit length."""
    eye = tuple(float(x) for x in camera["from"])
    forward = normalize(sub(tuple(camera["at"]), eye))
    right = normalize(cross(forward, tuple(camera.get("up", [0, 1, 0]))))
    up = cross(right, forward)
    return eye, forward, right, up


def camera_vfov(camera):
    """The camera's vertical field of view in degrees."""
    return camera.get("vfov", 40)


class PinholeCamera:
    """The course's pinhole camera for an image of width x height pixels: rays from the eye through the image."""

    def __init__(self, camera, width, height):
        self.eye, self.forward, self.right, self.up = camera_basis(camera)
        self.width, self.height = width, height
        self.half_height = math.tan(math.radians(camera_vfov(camera)) / 2)
        self.half_width = self.half_height * width / height

    def direction(self, px, py):
        """The unit direction through image point (px, py), in pixels from the top-left corner (a pixel's
        centre is x + 0.5, y + 0.5)."""
        a = (2 * px / self.width - 1) * self.half_width
        b = (1 - 2 * py / self.height) * self.half_height
        return normalize(add(self.forward, add(mul(self.right, a), mul(self.up, b))))


# --- ray hits --------------------------------------------------------------------------------------------

def hit_quad(o, d, quad, t_min=1e-6):
    """The distance t > t_min along the ray o + t d to the quad (origin, u, v) (either side), or None."""
    q0, u, v = quad
    n = cross(u, v)
    den = dot(n, d)
    if abs(den) < 1e-12:
        return None
    t = dot(n, sub(q0, o)) / den
    if t <= t_min:
        return None
    p = sub(add(o, mul(d, t)), q0)
    w = mul(n, 1 / dot(n, n))
    a = dot(w, cross(p, v))
    b = dot(w, cross(u, p))
    return t if 0 <= a <= 1 and 0 <= b <= 1 else None


def hit_sphere(o, d, sphere):
    """The nearest distance t > 1e-6 along the ray o + t d (d unit length) to the sphere (center, radius)."""
    c, r = sphere
    oc = sub(o, c)
    b = dot(oc, d)
    disc = b * b - (dot(oc, oc) - r * r)
    if disc < 0:
        return None
    s = math.sqrt(disc)
    for t in (-b - s, -b + s):
        if t > 1e-6:
            return t
    return None
