"""Chapter 06: a warp and its density. Stratified points of the unit square, the same points warped to the
cosine-weighted hemisphere (sin θ = √u₁, φ = 2π u₂: seen from above they fill the disk uniformly), and the
density of the warped directions against pdf(ω) = cos θ / π and the uniform 1/(2π). Then MIS's weights
w_l = 1 / (1 + (p_b / p_l)^β) (mis.hpp, one sample each): balance β = 1, power β = 2, and the maximum
heuristic they tend to as β grows."""

import math
import random

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, label, new_figure

SIDE = 16


def stratified_points(seed=6):
    rng = random.Random(seed)
    return [((i + rng.random()) / SIDE, (j + rng.random()) / SIDE) for j in range(SIDE) for i in range(SIDE)]


def warp_figure():
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
    return fig


def mis_weight(ratio, exponent):
    """w_l for p_l / p_b = ratio: 1 / (1 + (p_b / p_l)^β)."""
    return 1 / (1 + (1 / ratio) ** exponent)


def mis_figure():
    fig, (ax,) = new_figure(7.0, 3.4)
    ax.set_aspect("auto")
    ax.axis("on")
    ratios = [10 ** (k / 40) for k in range(-120, 121)]
    for exponent, style, name in ((1, "-", "balance, β = 1"), (2, "--", "power, β = 2")):
        ax.plot(ratios, [mis_weight(r, exponent) for r in ratios], color=LIGHT, lw=2, ls=style,
                label=f"w_l, {name}")
        ax.plot(ratios, [1 - mis_weight(r, exponent) for r in ratios], color=RAY, lw=2, ls=style,
                label=f"w_b, {name}")
    ax.step([ratios[0], 1, ratios[-1]], [0, 1, 1], where="post", color=QUIET, lw=1, ls=":",
            label="w_l, β → ∞: the larger density takes all")
    ax.axvline(1, color=SURFACE, lw=0.6)
    ax.text(0.6, 0.5, "p_l = p_b: ½ each", fontsize=8, color=SURFACE, ha="right")
    ax.set_xscale("log")
    ax.set_xlabel("p_l / p_b  (light sampling's density over the BRDF's, at one direction)")
    ax.set_ylabel("weight")
    ax.legend(fontsize=8, frameon=False, loc="center left", bbox_to_anchor=(1.0, 0.5))
    ax.set_title("MIS weights: w_l + w_b = 1 at every direction")
    return fig


def figures():
    return {"06_monte_carlo/images/diagram_warp.svg": warp_figure(),
            "06_monte_carlo/images/diagram_mis_weights.svg": mis_figure()}
