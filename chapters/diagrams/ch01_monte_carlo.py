"""Chapter 01's Monte Carlo primer: the estimator's error narrowing like 1/√N, and the two ways of making a
sampler: inverting a cumulative distribution, and a change of variables with its Jacobian (the disk)."""

import math
import random

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, label, new_figure

EDGE = 0.3        # the integrand: 1 left of the edge, 0 right of it, so I = EDGE
RUNS = 6
MAX_SAMPLES = 4096
SIDE = 16         # stratified points per side for the disks


def running_means(rng: random.Random) -> list[float]:
    """F_N for N = 1 … MAX_SAMPLES of one run: the mean of f(X_i) / p(X_i), X_i uniform, p = 1."""
    means, total = [], 0.0
    for n in range(1, MAX_SAMPLES + 1):
        total += 1.0 if rng.random() < EDGE else 0.0
        means.append(total / n)
    return means


def estimator_figure():
    fig = new_figure(10.0, 3.4, panels=2)[0]
    integrand, runs = fig.axes
    for ax in fig.axes:
        ax.set_aspect("auto")
        ax.axis("on")
    rng = random.Random(1)
    integrand.fill_between([0, EDGE], [1, 1], color=LIGHT, alpha=0.3)
    integrand.plot([0, EDGE, EDGE, 1], [1, 1, 0, 0], color=SURFACE, lw=2)
    xs = [rng.random() for _ in range(16)]
    integrand.plot(xs, [1.0 if x < EDGE else 0.0 for x in xs], "o", color=RAY, ms=4)
    label(integrand, (0.15, 0.5), f"I = {EDGE}", color=ACCENT)
    integrand.set_xlabel("x (across a pixel)")
    integrand.set_ylabel("f(x)")
    integrand.set_ylim(-0.1, 1.2)
    integrand.set_title("f: 1 left of an edge; 16 uniform samples")

    sigma = math.sqrt(EDGE * (1 - EDGE))
    # Every N up to 64, then every 1/32 of an octave: the curves look the same, the SVG is a tenth the size.
    ns = sorted({n for n in range(1, 65)} | {round(2 ** (k / 32)) for k in range(192, 385)})
    for _ in range(RUNS):
        means = running_means(rng)
        runs.plot(ns, [means[n - 1] for n in ns], color=RAY, lw=0.8, alpha=0.8)
    for k, style in ((1, "--"), (2, ":")):
        for sign in (1, -1):
            runs.plot(ns, [EDGE + sign * k * sigma / math.sqrt(n) for n in ns], color=ACCENT, lw=1.2, ls=style)
    runs.axhline(EDGE, color=SURFACE, lw=1)
    runs.set_xscale("log", base=2)
    runs.set_ylim(-0.05, 1.05)
    runs.set_xlabel("N (samples)")
    runs.set_ylabel("F_N")
    label(runs, (12, 0.9), "I ± σ/√N (dashed), ± 2σ/√N (dotted)", color=ACCENT, fontsize=9, ha="left")
    runs.set_title(f"{RUNS} runs of F_N: the band narrows like 1/√N")
    return fig


def marginal_cdf(x: float) -> float:
    """The cumulative distribution of the marginal density x + 1/2 on [0, 1]."""
    return (x * x + x) / 2


def sampling_figure():
    fig = new_figure(11.0, 3.6, panels=3)[0]
    inversion, naive, uniform = fig.axes
    inversion.set_aspect("auto")
    inversion.axis("on")
    grid = [i / 200 for i in range(201)]
    inversion.plot(grid, [marginal_cdf(x) for x in grid], color=SURFACE, lw=2, label="F(x) = (x² + x)/2")
    inversion.plot(grid, [x + 0.5 for x in grid], color=LIGHT, lw=2, ls="--", label="p(x) = x + ½")
    for k in range(12):
        u = (k + 0.5) / 12
        x = (math.sqrt(1 + 8 * u) - 1) / 2
        inversion.plot([0, x, x], [u, u, 0], color=RAY, lw=0.7)
    inversion.set_xlim(0, 1)
    inversion.set_ylim(0, 1.55)
    inversion.set_xlabel("x = F⁻¹(u)")
    inversion.set_ylabel("u")
    inversion.legend(fontsize=8, frameon=False, loc="upper left")
    inversion.set_title("inversion: even u, x dense where p is high")

    rng = random.Random(6)
    points = [((i + rng.random()) / SIDE, (j + rng.random()) / SIDE) for j in range(SIDE) for i in range(SIDE)]
    circle = [2 * math.pi * i / 200 for i in range(201)]
    for ax, radius, caption, title in (
            (naive, lambda u1: u1, "r = u₁: density 1/(2πr)", "wrong: points crowd the centre"),
            (uniform, math.sqrt, "r = √u₁: density 1/π", "the Jacobian r undone: uniform")):
        ax.plot([math.cos(a) for a in circle], [math.sin(a) for a in circle], color=SURFACE)
        ax.scatter([radius(u1) * math.cos(2 * math.pi * u2) for u1, u2 in points],
                   [radius(u1) * math.sin(2 * math.pi * u2) for u1, u2 in points], s=5,
                   c=[RAY if u1 < 0.5 else QUIET for u1, _ in points])
        label(ax, (0, -1.2), caption + ",  φ = 2π u₂", fontsize=9)
        ax.set_title(title)
    return fig


def figures():
    return {"01_ray_generation/images/diagram_estimator.svg": estimator_figure(),
            "01_ray_generation/images/diagram_sampling.svg": sampling_figure()}
