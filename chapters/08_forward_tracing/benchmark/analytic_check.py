#!/usr/bin/env python3
"""Cycles' units and camera against an exact image: ch04_analytic.json (a diffuse plane under one quad lamp).

Every point of the plane sees the whole lamp and nothing else can light it (the lamp's albedo is black), so
its radiance is exactly albedo / pi times Lambert's polygon irradiance, E = L/2 * |sum_i theta_i n . g_i|, on
the lamp's emitting side (u x v) and 0 behind it. This script computes that per pixel (the mean of a 4x4 grid
of points in the pixel: a box filter) and compares a render of the scene (a PFM, e.g. by cycles_scene.py):

    blender -b --factory-startup --python cycles_scene.py -- --scene assets/scenes/ch04_analytic.json \\
        --size 150 --spp 256 --seed 1 --threads 2 --out analytic.pfm
    python3 analytic_check.py --scene assets/scenes/ch04_analytic.json --image analytic.pfm

It prints the ratio render / exact over the lit floor (pixels whose 3x3 neighbourhood is lit floor), by band of
rows and of columns (a camera mismatch would show as a trend), and the lamp's own pixels. The camera's rays and
the lamp's hit test come from scene_geometry.py (as against_cycles.py's region map casts them), the PFM reader
from against_cycles.py.
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from against_cycles import read_pfm  # noqa: E402
from scene_geometry import PinholeCamera, add, cross, dot, hit_quad, mul, normalize, quad_corners, sub  # noqa: E402


def exact_floor(p, n, lamp, radiance, albedo):
    o, u, v = lamp
    corners = quad_corners(lamp)
    ln = normalize(cross(u, v))
    if dot(sub(p, o), ln) <= 0:
        return 0.0, False  # behind the one-sided lamp
    vs = [normalize(sub(c, p)) for c in corners]
    s = 0.0
    for i in range(4):
        a, b = vs[i], vs[(i + 1) % 4]
        theta = math.acos(max(-1.0, min(1.0, dot(a, b))))
        g = normalize(cross(a, b))
        s += theta * dot(n, g)
    return albedo / math.pi * radiance / 2 * abs(s), True


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scene", required=True)
    ap.add_argument("--image", required=True)
    args = ap.parse_args()
    scene = json.load(open(args.scene))
    img = read_pfm(args.image)
    W, H = img.width, img.height
    plane = next(s for s in scene["shapes"] if s["type"] == "plane")
    lampq = next(s for s in scene["shapes"] if s["type"] == "quad")
    mats = scene["materials"]
    albedo = mats[plane["material"]]["albedo"]
    emission = mats[lampq["material"]]["emission"]
    lamp = (tuple(lampq["origin"]), tuple(lampq["u"]), tuple(lampq["v"]))
    n = normalize(tuple(plane["normal"]))
    p0 = tuple(plane["point"])
    camera = PinholeCamera(scene["camera"], W, H)
    eye = camera.eye

    kinds, exact = [], []
    for y in range(H):
        for x in range(W):
            vals, kind = [], set()
            for j in range(4):
                for i in range(4):
                    d = camera.direction(x + (i + 0.5) / 4, y + (j + 0.5) / 4)
                    tl = hit_quad(eye, d, lamp, t_min=0)
                    den = dot(n, d)
                    tp = dot(n, sub(p0, eye)) / den if abs(den) > 1e-12 else -1
                    if tl is not None and (tp <= 0 or tl < tp):
                        kind.add("lamp_front" if dot(d, cross(lamp[1], lamp[2])) < 0 else "lamp_back")
                        vals.append([emission[c] if "lamp_front" in kind else 0.0 for c in range(3)])
                    elif tp > 0:
                        e, lit = exact_floor(add(eye, mul(d, tp)), n, lamp, 1.0, 1.0)
                        kind.add("lit" if lit else "dark")
                        vals.append([albedo[c] * emission[c] * e for c in range(3)])
                    else:
                        kind.add("sky")
                        vals.append([0.0, 0.0, 0.0])
            kinds.append(kind.pop() if len(kind) == 1 else None)
            exact.append([sum(v[c] for v in vals) / len(vals) for c in range(3)])

    def keep(x, y, k):
        return all(0 <= x + i < W and 0 <= y + j < H and kinds[(y + j) * W + x + i] == k
                   for j in (-1, 0, 1) for i in (-1, 0, 1))

    for k in ("lit", "lamp_front"):
        px = [(x, y) for y in range(H) for x in range(W) if keep(x, y, k)]
        if not px:
            print("%s: no pixel" % k)
            continue
        num = sum(sum(img.at(x, y)) for x, y in px)
        den = sum(sum(exact[y * W + x]) for x, y in px)
        print("%-10s %6d pixels: render / exact = %.4f (render mean %.5f, exact mean %.5f)" %
              (k, len(px), num / den, num / 3 / len(px), den / 3 / len(px)))
        if k == "lit":
            for axis, name in ((1, "rows"), (0, "columns")):
                bands = {}
                for x, y in px:
                    key = (y if axis else x) * 5 // (H if axis else W)
                    s = bands.setdefault(key, [0.0, 0.0])
                    s[0] += sum(img.at(x, y))
                    s[1] += sum(exact[y * W + x])
                print("  by fifths of the %s: %s" % (name, "  ".join("%.4f" % (v[0] / v[1]) for _, v in
                                                                     sorted(bands.items()))))


if __name__ == "__main__":
    main()
