#!/usr/bin/env python3
"""Time to a relative MSE, the course against Blender Cycles, measured in one run (chapter 08's benchmark).

Runs Cycles (blender + cycles_scene.py) and one or more course commands alternately at lists of samples per
pixel, --repeats times each, reads every image (PFM), and measures its relative MSE against a converged
reference r = (A + B) / 2 made of the two cached halves that `ch07_error_study --cache DIR --size N` writes
(ch07_reference_cornell_N_8192spp_a.pfm and _b.pfm), exactly as chapter 07's error_study.cpp does:

    relMSE(x) = mean over pixels and channels of (x - r)^2 / (r^2 + 0.01)  -  relMSE(A, r)

(the second term is the reference's own noise: A - r = (A - B) / 2). With --cycles-reference-spp, Cycles is
measured the same way against its own reference, two halves that Cycles renders. It prints, as Markdown tables:
  * each renderer at each spp: median render time, median process wall time, the mean relative MSE, the share
    of the squared error held by the worst 1 % of pixels and the median pixel's error;
  * each renderer's time to --target (1e-3): interpolated in log-log between the two measured points that
    bracket the target, otherwise extrapolated from the nearest point with relMSE proportional to 1 / time
    (marked "extrapolated"); from render times and from process wall times;
  * how many times sooner each renderer reaches it than each other, by the issues' figure: Cycles' render time
    against a course program's whole process wall time (training passes, scene loading and BVH included);
  * the converged images' agreement: the mean of each region (walls, floor, ceiling, lamp, tall box, sphere;
    pixels whose 3x3 neighbourhood sees one shape) for each renderer at its highest spp, against the reference.

Render time is what each renderer reports for rendering alone, without start-up, scene loading or BVH build:
the course's summary line "time X s" (its render loop) and Cycles' own render_time (path tracing, without its
scene synchronisation), which cycles_scene.py reads from the render's metadata. Process wall time includes
everything (Blender's start-up, the scene build, the sphere's mesh and BVH, writing the image).

Example (from the repository root, with the lead's build):

    python3 chapters/08_forward_tracing/benchmark/against_cycles.py --reference-dir /work/ref --size 300 \\
        --cycles-spp 64,256,1024 --course-spp 64,256,1024 --repeats 2 --threads 2 \\
        --course "ch07=build/release/chapters/07_bsdf_refraction/ch07_bsdf_refraction --scene {scene} \\
                  --width {size} --height {size} --spp {spp} --seed {seed} --threads {threads} --quiet --out {png}"

Any course executable that takes these flags and prints the summary line "time X s" can be measured: one
--course flag per program, e.g. --course "ch12=build/release/chapters/12_path_guiding/ch12_path_guiding ...".
--cycles-variant "Cycles-guiding=--guiding" adds Cycles with its path guiding (cycles_scene.py refuses it where
Blender was built without OpenPGL, as Debian's 3.4.1 is); --cycles-spp "" leaves Cycles out (course programs only).

Template fields: {scene} {size} {spp} {seed} {threads}, {out} (the PFM that is read afterwards) and {png}
(the same name ending in .png: the course's executables take a PNG name and write the PFM beside it). Seeds
are 11, 12, ... per repeat (never the reference halves' 1001 and 1002). Only Python's standard library is used,
with scene_geometry.py beside this script (vectors, the course's transform and camera, ray hits).
"""
import argparse
import json
import math
import os
import re
import shlex
import struct
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "..", "..", ".."))

sys.path.insert(0, HERE)  # scene_geometry.py, beside this script
from scene_geometry import (PinholeCamera, add, box_quads, camera_basis, cross, dot, hit_quad,  # noqa: E402
                            hit_sphere, mesh_triangles, mul, normalize, sub)


# --- images ----------------------------------------------------------------------------------------------

class Image:
    """Linear RGB, row 0 at the top (as the course's Image), from a PFM (rows bottom up)."""

    def __init__(self, width, height, data):
        self.width, self.height, self.data = width, height, data  # data: top row first, RGB floats

    def at(self, x, y):
        i = 3 * (y * self.width + x)
        return self.data[i:i + 3]


def read_pfm(path):
    with open(path, "rb") as f:
        raw = f.read()
    fields, pos = [], 0
    while len(fields) < 4:  # "PF", width, height, scale, each followed by whitespace
        while raw[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not raw[pos:pos + 1].isspace():
            pos += 1
        fields.append(raw[start:pos].decode("ascii"))
    pos += 1  # the one whitespace byte that ends the header
    if fields[0] != "PF":
        raise SystemExit("%s: not a colour PFM" % path)
    width, height, scale = int(fields[1]), int(fields[2]), float(fields[3])
    n = width * height * 3
    values = struct.unpack(("<" if scale < 0 else ">") + "%df" % n, raw[pos:pos + 4 * n])
    rows = [values[(height - 1 - y) * width * 3:(height - y) * width * 3] for y in range(height)]
    data = [v for row in rows for v in row]
    if not all(math.isfinite(v) for v in data):
        raise SystemExit("%s: holds non-finite values" % path)
    return Image(width, height, data)


def relative_mse(x, r):
    """mean over pixels and channels of (x - r)^2 / (r^2 + 0.01), as rt::compare."""
    s = 0.0
    for a, b in zip(x.data, r.data):
        d = a - b
        s += d * d / (b * b + 0.01)
    return s / len(r.data)


def pixel_errors(x, r):
    """Each pixel's relative squared error summed over its channels, as error_study.cpp's pixel_errors."""
    xd, rd = x.data, r.data
    out = []
    for i in range(0, len(rd), 3):
        e = 0.0
        for c in range(3):
            d = xd[i + c] - rd[i + c]
            e += d * d / (rd[i + c] * rd[i + c] + 0.01)
        out.append(e)
    return out


def error_shape(x, r):
    """(share of the squared error in the worst 1 % of pixels, the median pixel's error per channel)."""
    e = sorted(pixel_errors(x, r), reverse=True)
    n = max(1, len(e) // 100)
    total = sum(e)
    return (sum(e[:n]) / total if total > 0 else 0.0), e[len(e) // 2] / 3


# --- regions: which shape each pixel sees, by an analytic ray cast of the scene JSON -------------------------

def scene_primitives(scene):
    """[(region name, kind, data)]: quads (origin, u, v) and spheres (center, radius), with a name per shape."""
    eye, forward, right, _ = camera_basis(scene["camera"])
    materials = scene.get("materials", {})
    prims = []
    for i, s in enumerate(scene.get("shapes", [])):
        mat = materials.get(s["material"], {})
        if s["type"] == "quad":
            o, u, v = tuple(s["origin"]), tuple(s["u"]), tuple(s["v"])
            n = normalize(cross(u, v))
            centre = add(o, mul(add(u, v), 0.5))
            axis = max(range(3), key=lambda k: abs(n[k]))
            if max(mat.get("emission", [0])) > 0:
                name = "lamp"
            elif axis == 1:
                name = "ceiling" if centre[1] > eye[1] else "floor"
            elif abs(dot(n, forward)) > 0.9:
                name = "back wall"
            else:
                name = ("left wall" if dot(sub(centre, eye), right) < 0 else "right wall")
            name += " (%s)" % s["material"]
            prims.append((name, "quad", (o, u, v)))
        elif s["type"] == "box":
            lo, hi = s["min"], s["max"]
            name = "box shapes[%d] (%s)" % (i, s["material"])
            if (hi[1] - lo[1]) > 1.5 * (hi[0] - lo[0]):
                name = "tall box (%s)" % s["material"]
            for quad in box_quads(s):
                prims.append((name, "quad", quad))
        elif s["type"] == "sphere":
            prims.append(("sphere (%s)" % s["material"], "sphere", (tuple(s["center"]), float(s["radius"]))))
        elif s["type"] == "mesh":
            # Not cast triangle by triangle (too slow here): pixels whose ray meets its bounding box first are
            # left out of every region.
            points = [p for tri in mesh_triangles(s, os.path.dirname(scene["_path"])) for p in tri]
            lo = tuple(min(p[k] for p in points) for k in range(3))
            hi = tuple(max(p[k] for p in points) for k in range(3))
            prims.append((None, "box", (lo, hi)))
        else:
            prims.append((None, s["type"], None))  # not cast: pixels seeing it may be mislabelled
    return prims


def hit_box(o, d, box):
    """The distance t > 1e-6 along o + t d to the axis-aligned box (lo, hi), or None (slabs)."""
    lo, hi = box
    t0, t1 = 1e-6, float("inf")
    for k in range(3):
        if abs(d[k]) < 1e-15:
            if not lo[k] <= o[k] <= hi[k]:
                return None
            continue
        a, b = (lo[k] - o[k]) / d[k], (hi[k] - o[k]) / d[k]
        t0, t1 = max(t0, min(a, b)), min(t1, max(a, b))
    return t0 if t0 <= t1 else None


def region_map(scene, width, height):
    """Each pixel's region name (the first shape its centre's camera ray hits), None at a boundary."""
    prims = scene_primitives(scene)
    camera = PinholeCamera(scene["camera"], width, height)
    hits = {"quad": hit_quad, "sphere": hit_sphere, "box": hit_box}
    sky = "sky" if any(light["type"] == "environment" for light in scene.get("lights", [])) else None
    ids = []
    for y in range(height):
        for x in range(width):
            d = camera.direction(x + 0.5, y + 0.5)
            best, who = float("inf"), sky
            for name, kind, data in prims:
                if data is None:
                    continue
                t = hits[kind](camera.eye, d, data)
                if t is not None and t < best:
                    best, who = t, name
            ids.append(who)
    # Keep a pixel only when its 3x3 neighbourhood sees the same region (no edges, no mixed pixels).
    out = [None] * (width * height)
    for y in range(1, height - 1):
        for x in range(1, width - 1):
            n = ids[y * width + x]
            if n is not None and all(ids[(y + j) * width + x + i] == n for j in (-1, 0, 1) for i in (-1, 0, 1)):
                out[y * width + x] = n
    return out


def region_means(image, regions):
    sums, counts = {}, {}
    for i, name in enumerate(regions):
        if name is None:
            continue
        s = sums.setdefault(name, [0.0, 0.0, 0.0])
        for c in range(3):
            s[c] += image.data[3 * i + c]
        counts[name] = counts.get(name, 0) + 1
    return {k: [v / counts[k] for v in s] for k, s in sums.items()}, counts


# --- running the renderers -------------------------------------------------------------------------------

def converged_reference(stem, size, render_half=None):
    """r = (A + B) / 2 from the halves STEM_a.pfm and STEM_b.pfm (render_half(seed, out) makes a missing one,
    seeds 1001 and 1002), and r's own relative MSE, relMSE(A, r)."""
    for half, seed in (("a", 1001), ("b", 1002)):
        if render_half and not os.path.exists(stem + "_%s.pfm" % half):
            partial = stem + "_%s_partial.pfm" % half
            render_half(seed, partial)
            os.replace(partial, stem + "_%s.pfm" % half)
    A, B = read_pfm(stem + "_a.pfm"), read_pfm(stem + "_b.pfm")
    if (A.width, A.height) != (size, size) or (B.width, B.height) != (size, size):
        raise SystemExit("against_cycles.py: the reference halves %s_{a,b}.pfm are not %dx%d" % (stem, size, size))
    ref = Image(A.width, A.height, [0.5 * (a + b) for a, b in zip(A.data, B.data)])
    return ref, relative_mse(A, ref)


def run_command(argv, log):
    start = time.perf_counter()
    proc = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.perf_counter() - start
    with open(log, "w") as f:
        f.write(" ".join(shlex.quote(a) for a in argv) + "\n" + proc.stdout)
    if proc.returncode != 0:
        sys.stderr.write(proc.stdout[-3000:])
        raise SystemExit("against_cycles.py: command failed (status %d): %s" % (proc.returncode, " ".join(argv)))
    return proc.stdout, wall


def run_cycles(args, spp, seed, out, log, extra=()):
    argv = [args.blender, "-b", "--factory-startup", "--python", os.path.join(HERE, "cycles_scene.py"), "--",
            "--scene", args.scene, "--size", str(args.size), "--spp", str(spp), "--seed", str(seed),
            "--threads", str(args.threads), "--out", out, *extra]
    text, wall = run_command(argv, log)
    m = re.search(r"cycles_scene: render_seconds ([0-9.]+)", text)
    if not m:
        raise SystemExit("against_cycles.py: no render_seconds line from cycles_scene.py (see %s)" % log)
    op_seconds = float(m.group(1))
    m = re.search(r"cycles_render_time ([0-9.]+)", text)
    if args.cycles_time == "render" and not m:
        raise SystemExit("against_cycles.py: Cycles reported no render_time (see %s)" % log)
    render = float(m.group(1)) if m else op_seconds
    if args.cycles_time == "operator":
        render = op_seconds
    return render, wall, op_seconds


def run_course(args, template, spp, seed, out, log):
    command = template.format(scene=args.scene, size=args.size, spp=spp, seed=seed, threads=args.threads,
                              out=out, png=out[:-len(".pfm")] + ".png")
    text, wall = run_command(shlex.split(command), log)
    m = re.search(r"^\s*time ([0-9.]+) s", text, re.M)
    if not m:
        raise SystemExit("against_cycles.py: no 'time X s' line in the course's summary (see %s)" % log)
    if re.search(r"all pixels finite: NO", text):
        raise SystemExit("against_cycles.py: the course's image has non-finite pixels (see %s)" % log)
    return float(m.group(1)), wall, None


def is_cycles(how):
    """A renderer's `how` is cycles_scene.py's extra arguments (a list) for Cycles, a command template for the course."""
    return isinstance(how, list)


def print_sooner_by(renderers, to_target):
    """How many times sooner each renderer (row) reaches the target than each other (column), by the issues'
    figure: Cycles' render time against a course program's whole process wall time."""
    names = [name for name, _, _ in renderers]
    own = {name: to_target[name][0 if is_cycles(how) else 1] for name, how, _ in renderers}
    print("\n## Sooner by: row against column (Cycles' render time, a course program's process wall time)\n")
    print("| renderer | time to target | " + " | ".join("than %s" % n for n in names) + " |")
    print("|---|---|" + "---|" * len(names))
    for row in names:
        print("| %s | %.1f s | " % (row, own[row]) + " | ".join(
            "-" if row == col else "%.2fx" % (own[col] / own[row]) for col in names) + " |")


def median(v):
    v = sorted(v)
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def time_to_target(points, target):
    """points: [(time, relMSE)] in order of spp. Returns (time, how)."""
    pts = [(t, e) for t, e in points if t > 0 and e > 0]
    if not pts:
        return float("nan"), "no error measured"
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if (e0 - target) * (e1 - target) <= 0 and e0 != e1:
            s = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + s * (math.log(t1) - math.log(t0))), "interpolated"
    # Not bracketed: from the point nearest the target in error, relMSE proportional to 1 / time.
    t, e = min(pts, key=lambda p: abs(math.log(p[1] / target)))
    return t * e / target, "extrapolated"


def parse_spp(text):
    return [int(v) for v in text.split(",") if v.strip()]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    p.add_argument("--scene", default=os.path.join(REPO, "assets", "scenes", "cornell.json"))
    p.add_argument("--size", type=int, default=300)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--repeats", type=int, default=2)
    p.add_argument("--target", type=float, default=1e-3)
    p.add_argument("--blender", default="blender")
    p.add_argument("--cycles-spp", default="64,256")
    p.add_argument("--course-spp", default="64,256,1024")
    p.add_argument("--course", action="append", default=[], metavar="NAME=TEMPLATE",
                   help="a course command (repeatable); fields {scene} {size} {spp} {seed} {threads}, {out} (the PFM "
                        "read) and {png} (the same name ending in .png)")
    p.add_argument("--cycles-variant", action="append", default=[], metavar="NAME=ARGS",
                   help="Cycles again with more cycles_scene.py arguments (repeatable), measured against Cycles' "
                        "reference, e.g. \"Cycles-guiding=--guiding\"")
    p.add_argument("--cycles-time", choices=["render", "operator"], default="render",
                   help="Cycles' render time: its own path-tracing time (render) or the wall time of "
                        "bpy.ops.render.render, synchronisation and BVH build included (operator)")
    p.add_argument("--reference-dir", default=".")
    p.add_argument("--reference-stem", default="ch07_reference_cornell_{size}_8192spp")
    p.add_argument("--reference-command", default=None, metavar="TEMPLATE",
                   help="for any scene: a course command (fields as --course) that renders the reference's two "
                        "halves at --reference-spp with seeds 1001 and 1002, as reference_SCENE_SIZE_SPPspp_{a,b}.pfm "
                        "in --reference-dir, unless they are there already (then --reference-stem is not used)")
    p.add_argument("--reference-spp", type=int, default=2048)
    p.add_argument("--cycles-reference-spp", type=int, default=0,
                   help="measure Cycles against its own converged reference: two halves rendered by Cycles at this "
                        "spp (seeds 1001 and 1002), cycles_reference_SCENE_SIZE_SPPspp_{a,b}.pfm in "
                        "--reference-dir; 0 (the default): against the course's reference")
    p.add_argument("--work", default=None, help="folder for the renders and logs (default: a temporary one)")
    p.add_argument("--json", default=None, help="also write every measurement to this JSON file")
    args = p.parse_args()
    args.scene = os.path.abspath(args.scene)

    scene_name = os.path.splitext(os.path.basename(args.scene))[0]
    os.makedirs(args.reference_dir, exist_ok=True)  # where the reference halves are cached
    if args.reference_command:
        stem = os.path.join(args.reference_dir, "reference_%s_%d_%dspp" % (scene_name, args.size,
                                                                         args.reference_spp))
        ref, noise = converged_reference(stem, args.size, lambda seed, out: run_course(
            args, args.reference_command, args.reference_spp, seed, out, out[:-4] + ".log"))
    else:
        stem = os.path.join(args.reference_dir, args.reference_stem.format(size=args.size))
        ref, noise = converged_reference(stem, args.size)
    # Cycles against its own converged reference, or against the course's.
    cycles_ref, cycles_noise = ref, noise
    if args.cycles_reference_spp and parse_spp(args.cycles_spp):
        cycles_stem = os.path.join(args.reference_dir, "cycles_reference_%s_%d_%dspp" % (
            scene_name, args.size, args.cycles_reference_spp))
        cycles_ref, cycles_noise = converged_reference(cycles_stem, args.size, lambda seed, out: run_cycles(
            args, args.cycles_reference_spp, seed, out, out[:-4] + ".log"))
        print("converged means, Cycles' reference / the course's: %.4f (their own relative MSE %.3e and %.3e)" %
              (sum(cycles_ref.data) / sum(ref.data), cycles_noise, noise), flush=True)

    # (name, how, spps): how is a course command template (a string) or cycles_scene.py's extra arguments (a list).
    renderers = [("Cycles", [], parse_spp(args.cycles_spp))] if parse_spp(args.cycles_spp) else []
    for item in args.cycles_variant:
        name, sep, extra = item.partition("=")
        if not sep or " " in name or not renderers:
            raise SystemExit("against_cycles.py: --cycles-variant must be NAME=ARGS, with Cycles run, got %r" % item)
        renderers.append((name, shlex.split(extra), parse_spp(args.cycles_spp)))
    for item in args.course:
        name, sep, template = item.partition("=")
        if not sep or not template.strip() or " " in name:
            raise SystemExit("against_cycles.py: --course must be NAME=TEMPLATE, got %r" % item)
        renderers.append((name, template, parse_spp(args.course_spp)))
    if len(renderers) < 2 or not args.course:
        raise SystemExit("against_cycles.py: give at least one --course NAME=TEMPLATE, and Cycles or a second one")

    work = args.work or tempfile.mkdtemp(prefix="against_cycles_")
    os.makedirs(work, exist_ok=True)
    load_before = os.getloadavg()
    print("against_cycles: %s %dx%d, %d threads, %d repeats, target relative MSE %g; reference %s_{a,b}.pfm "
          "(its own relative MSE %.3e, subtracted); work folder %s" %
          (os.path.basename(args.scene), args.size, args.size, args.threads, args.repeats, args.target, stem,
           noise, work), flush=True)
    print("load average before: %.2f %.2f %.2f" % load_before, flush=True)

    results = {name: {spp: [] for spp in spps} for name, _, spps in renderers}
    levels = max(len(spps) for _, _, spps in renderers)
    for rep in range(args.repeats):
        seed = 11 + rep
        order = renderers if rep % 2 == 0 else list(reversed(renderers))  # who goes first alternates too
        for level in range(levels):
            for name, template, spps in order:
                if level >= len(spps):
                    continue
                spp = spps[level]
                out = os.path.join(work, "%s_%dspp_seed%d.pfm" % (name, spp, seed))
                log = out[:-4] + ".log"
                if is_cycles(template):
                    render, wall, op = run_cycles(args, spp, seed, out, log, template)
                else:
                    render, wall, op = run_course(args, template, spp, seed, out, log)
                img = read_pfm(out)
                if (img.width, img.height) != (args.size, args.size):
                    raise SystemExit("against_cycles.py: %s is %dx%d" % (out, img.width, img.height))
                own_ref, own_noise = (cycles_ref, cycles_noise) if is_cycles(template) else (ref, noise)
                raw = relative_mse(img, own_ref)
                worst, med = error_shape(img, own_ref)
                results[name][spp].append({"seed": seed, "render_s": render, "wall_s": wall, "op_s": op,
                                           "rel_mse": max(0.0, raw - own_noise), "rel_mse_raw": raw,
                                           "worst1_share": worst, "median_pixel": med, "pfm": out,
                                           "load1": os.getloadavg()[0]})
                print("  repeat %d: %-8s %5d spp seed %d: render %.3f s, wall %.3f s%s, relMSE %.4e" %
                      (rep + 1, name, spp, seed, render, wall,
                       "" if op is None else " (render operator %.3f s)" % op, max(0.0, raw - own_noise)),
                      flush=True)
    load_after = os.getloadavg()

    print("\n## Each renderer at each spp (%d repeats: median seconds, mean relative MSE)\n" % args.repeats)
    print("| renderer | spp | render s | process wall s | relative MSE | relMSE per repeat | worst 1 % share | "
          "median pixel |")
    print("|---|---|---|---|---|---|---|---|")
    summary = {}
    for name, _, spps in renderers:
        for spp in spps:
            runs = results[name][spp]
            t = median([r["render_s"] for r in runs])
            w = median([r["wall_s"] for r in runs])
            e = sum(r["rel_mse"] for r in runs) / len(runs)
            share = sum(r["worst1_share"] for r in runs) / len(runs)
            med = sum(r["median_pixel"] for r in runs) / len(runs)
            summary.setdefault(name, []).append((spp, t, w, e))
            print("| %s | %d | %.2f | %.2f | %.4e | %s | %.0f %% | %.2e |" %
                  (name, spp, t, w, e, ", ".join("%.3e" % r["rel_mse"] for r in runs), 100 * share, med))

    print("\n## Time to a relative MSE of %g\n" % args.target)
    print("| renderer | from render time | how | from process wall time | how |")
    print("|---|---|---|---|---|")
    to_target = {}
    for name, _, _ in renderers:
        pts = summary[name]
        tr, how_r = time_to_target([(t, e) for _, t, _, e in pts], args.target)
        tw, how_w = time_to_target([(w, e) for _, _, w, e in pts], args.target)
        to_target[name] = (tr, tw)
        print("| %s | %.1f s | %s | %.1f s | %s |" % (name, tr, how_r, tw, how_w))
    print_sooner_by(renderers, to_target)

    print("\n## Converged agreement: region means at the highest spp against the reference\n")
    scene = json.load(open(args.scene))
    scene["_path"] = args.scene
    regions = region_map(scene, args.size, args.size)
    ref_means, counts = region_means(ref, regions)
    names = sorted(ref_means, key=lambda n: -counts[n])
    for name, _, spps in renderers:
        top = max(spps)
        print("%s at %d spp (mean of %d repeats; ratio = renderer / reference, per channel R G B, and the "
              "spread of the repeats' luminance-weighted ratio):\n" % (name, top, len(results[name][top])))
        print("| region | pixels | reference R G B | %s R G B | ratio R G B | ratio per repeat |" % name)
        print("|---|---|---|---|---|---|")
        per_repeat = [region_means(read_pfm(r["pfm"]), regions)[0] for r in results[name][top]]
        for region in names + ["whole image"]:
            if region == "whole image":
                rm = [sum(ref.data[c::3]) / (len(ref.data) // 3) for c in range(3)]
                reps = []
                for r in results[name][top]:
                    im = read_pfm(r["pfm"])
                    reps.append([sum(im.data[c::3]) / (len(im.data) // 3) for c in range(3)])
                count = args.size * args.size
            else:
                rm = ref_means[region]
                reps = [m[region] for m in per_repeat]
                count = counts[region]
            mean = [sum(m[c] for m in reps) / len(reps) for c in range(3)]
            ratio = ["%.3f" % (mean[c] / rm[c]) if rm[c] > 1e-6 else "-" for c in range(3)]
            lum = lambda v: 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2]
            rep_ratios = ", ".join("%.3f" % (lum(m) / lum(rm)) for m in reps) if lum(rm) > 0 else "-"
            print("| %s | %d | %.4f %.4f %.4f | %.4f %.4f %.4f | %s | %s |" %
                  (region, count, rm[0], rm[1], rm[2], mean[0], mean[1], mean[2], " ".join(ratio), rep_ratios))
        print()
    print("load average before %.2f %.2f %.2f, after %.2f %.2f %.2f (1, 5, 15 min); nproc %d" %
          (load_before + load_after + (os.cpu_count() or 0,)))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"args": vars(args), "reference_noise": noise, "cycles_reference_noise": cycles_noise,
                       "load_before": load_before,
                       "load_after": load_after, "results": {n: {str(s): v for s, v in d.items()}
                                                             for n, d in results.items()}}, f, indent=1)


if __name__ == "__main__":
    main()
