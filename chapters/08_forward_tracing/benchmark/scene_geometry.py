"""The geometry of a course scene (assets/scenes/*.json) in plain Python, shared by chapter 08's benchmark scripts.

Vectors are tuples of three numbers. This module holds what the scripts must compute exactly as the course
does: the shape transform, a box's six faces, the pinhole camera and a ray's first hit on a quad or a sphere.
Only Python's standard library is used, so it imports both in the system's Python (against_cycles.py,
analytic_check.py) and in Blender's bundled one (cycles_scene.py).
"""
import math

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
