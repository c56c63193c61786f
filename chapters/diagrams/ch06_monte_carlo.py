"""Chapter 06: a warp and its density. Stratified points of the unit square, the same points warped to the
cosine-weighted hemisphere (sin θ = √u₁, φ = 2π u₂: seen from above they fill the disk uniformly), and the
density of the warped directions against pdf(ω) = cos θ / π and the uniform 1/(2π)."""

import math
import random

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, label, new_figure

SIDE = 16


def stratified_points(seed=6):
    rng = random.Random(seed)
    return [((i + rng.random()) / SIDE, (j + rng.random()) / SIDE) for j in range(SIDE) for i in range(SIDE)]


def figures():
    fig = new_figure(11.0, 3.6, panels=3)[0]
    square, disk, density = fig.axes
    points = stratified_points()
    colours = [RAY if u1 < 0.5 else LIGHT for u1, _ in points]
    square.scatter([p[0] for p in points], [p[1] for p in points], s=5, c=colours)
    square.plot([0, 1, 1, 0, 0], [0, 0, 1, 1, 0], color=SURFACE)
    label(square, (0.5, -0.1), "u₁ →", fontsize=9)
    square.set_title("(u₁, u₂): stratified in the square")

    warped = [(math.sqrt(u1) * math.cos(2 * math.pi * u2), math.sqrt(u1) * math.sin(2 * math.pi * u2))
              for u1, u2 in points]
    disk.scatter([p[0] for p in warped], [p[1] for p in warped], s=5, c=colours)
    t = [2 * math.pi * i / 200 for i in range(201)]
    disk.plot([math.cos(a) for a in t], [math.sin(a) for a in t], color=SURFACE)
    label(disk, (0, -1.18), "sin θ = √u₁,  φ = 2π u₂  (seen from above)", fontsize=9)
    disk.set_title("warped: cosine-weighted directions")

    # The density of θ of many warped samples, per unit solid angle, against cos θ / π.
    density.set_aspect("auto")
    density.axis("on")
    bins = 18
    counts = [0] * bins
    rng = random.Random(7)
    samples = 200000
    for _ in range(samples):
        theta = math.asin(math.sqrt(rng.random()))
        counts[min(int(theta / (math.pi / 2) * bins), bins - 1)] += 1
    width = math.pi / 2 / bins
    centres, measured = [], []
    for k, count in enumerate(counts):
        lo, hi = k * width, (k + 1) * width
        solid_angle = 2 * math.pi * (math.cos(lo) - math.cos(hi))
        centres.append(math.degrees(lo + width / 2))
        measured.append(count / samples / solid_angle)
    density.bar(centres, measured, width=math.degrees(width) * 0.9, color=QUIET, label="warped samples")
    thetas = [i * 0.5 for i in range(181)]
    density.plot(thetas, [math.cos(math.radians(a)) / math.pi for a in thetas], color=ACCENT, lw=2,
                 label="cos θ / π")
    density.plot(thetas, [1 / (2 * math.pi)] * len(thetas), color=RAY, lw=2, ls="--", label="uniform 1/(2π)")
    density.set_xlabel("θ (degrees)")
    density.set_ylabel("density per steradian")
    density.legend(fontsize=8, frameon=False)
    density.set_title("the pdf the estimator divides by")
    return {"06_monte_carlo/images/diagram_warp.svg": fig}
