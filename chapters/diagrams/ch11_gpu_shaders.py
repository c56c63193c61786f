"""Chapter 11: the threads of a warp diverging. Each lane traces one path; Russian roulette ends the paths
after different numbers of bounces, but the warp runs in lock step until its longest path ends, the
finished lanes masked off. The share of lanes doing work is the warp's efficiency."""

import random

from matplotlib.patches import Rectangle

from figure_style import ACCENT, QUIET, RAY, label, new_figure

LANES = 8
SURVIVAL = 0.7


def path_lengths(seed=11):
    """Bounces of each lane's path: one at least, then each further one with probability SURVIVAL."""
    rng = random.Random(seed)
    lengths = []
    for _ in range(LANES):
        n = 1
        while rng.random() < SURVIVAL:
            n += 1
        lengths.append(n)
    return lengths


def figures():
    lengths = path_lengths()
    steps = max(lengths)
    fig, (ax,) = new_figure(8.0, 3.6)
    for lane, n in enumerate(lengths):
        y = LANES - 1 - lane
        for step in range(steps):
            active = step < n
            ax.add_patch(Rectangle((step, y), 0.92, 0.8, color=RAY if active else QUIET,
                                   alpha=0.85 if active else 0.25, hatch=None if active else "///"))
        label(ax, (-0.2, y + 0.4), f"lane {lane}", ha="right", fontsize=8)
    for step in range(steps):
        label(ax, (step + 0.46, -0.35), f"{step + 1}", fontsize=8)
    label(ax, (steps / 2, -0.9), "bounce (the warp executes every step for all its lanes)", fontsize=9)
    efficiency = sum(lengths) / (LANES * steps)
    label(ax, (steps + 0.3, LANES / 2), f"busy: {sum(lengths)} of {LANES * steps}\nlane-steps = "
                                        f"{efficiency:.0%}", ha="left", color=ACCENT, fontsize=10)
    ax.set_xlim(-1.5, steps + 3.2)
    ax.set_ylim(-1.2, LANES + 0.2)
    ax.set_title("a warp of 8 lanes: paths of different lengths (roulette, survival 0.7)")
    return {"11_gpu_shaders/images/diagram_warp_divergence.svg": fig}
