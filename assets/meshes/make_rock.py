#!/usr/bin/env python3
"""Writes suite_rock.ply beside this script: a faceted rock of 20,480 triangles for the scene-kind suite
(assets/scenes/suite_mesh_sky.json). An icosahedron split five times (each triangle into four, the new vertices
pushed out to the unit sphere), then every vertex moved along its direction by a sum of fixed waves and the
whole squashed to 0.7 of its height: bumps at several scales, as a scanned stone has. Binary little-endian
PLY, positions only (no normals: the course and Cycles both shade it faceted). Standard library only; the
same bytes on every run.

    python3 assets/meshes/make_rock.py
"""
import math
import os
import struct

LEVELS = 5
# (direction, frequency, amplitude): the bumps are a sum of cos(frequency · (p · direction) + phase).
WAVES = [((0.3, 0.9, 0.2), 2.0, 0.10), ((0.8, -0.2, 0.5), 3.5, 0.06), ((-0.5, 0.4, 0.75), 6.0, 0.035),
         ((0.1, -0.7, 0.7), 11.0, 0.02), ((0.9, 0.3, -0.3), 17.0, 0.012), ((-0.2, -0.1, 0.97), 29.0, 0.007)]


def normalize(v):
    n = math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    return (v[0] / n, v[1] / n, v[2] / n)


def icosphere(levels):
    t = (1 + math.sqrt(5)) / 2
    verts = [normalize(v) for v in [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                                    (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                pa, pb = verts[a], verts[b]
                verts.append(normalize(((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2)))
                middle[key] = len(verts) - 1
            return middle[key]
        faces = [f for a, b, c in faces
                 for ab, bc, ca in [(mid(a, b), mid(b, c), mid(c, a))]
                 for f in ((a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca))]
    return verts, faces


def displaced(p):
    r = 1.0
    for k, (d, frequency, amplitude) in enumerate(WAVES):
        d = normalize(d)
        r += amplitude * math.cos(frequency * (p[0] * d[0] + p[1] * d[1] + p[2] * d[2]) + 1.7 * k)
    return (r * p[0], 0.7 * r * p[1], r * p[2])


def main():
    verts, faces = icosphere(LEVELS)
    points = [displaced(p) for p in verts]
    lowest = min(p[1] for p in points)
    points = [(x, y - lowest, z) for x, y, z in points]  # resting on y = 0
    header = ("ply\nformat binary_little_endian 1.0\ncomment made by make_rock.py\n"
              "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(points), len(faces)))
    body = b"".join(struct.pack("<3f", *p) for p in points)
    body += b"".join(struct.pack("<B3i", 3, *f) for f in faces)
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "suite_rock.ply")
    with open(out + ".part", "wb") as f:
        f.write(header.encode("ascii") + body)
    os.replace(out + ".part", out)
    print("wrote %s: %d vertices, %d triangles" % (out, len(points), len(faces)))


if __name__ == "__main__":
    main()
