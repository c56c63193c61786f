"""Chapter 10: the à-trous kernel. Level i filters with the 5 × 5 B3-spline h_j h_k, h = (1, 4, 6, 4, 1)/16,
its taps 2^i pixels apart (the holes): three levels reach 17 × 17 pixels with 25 taps each (atrous.hpp).
And each guide's edge-stopping weight exp(−d² / s²) against its difference (edge_stopping.hpp), at the
defaults σ_c = 2, σ_n = 1, σ_z = 0.2, σ_a = 0.3 and at the lesson's first guess σ_n = 0.3, σ_z = 0.05,
σ_a = 0.1."""

import math

from matplotlib.patches import Rectangle

from figure_style import ACCENT, RAY, SURFACE, QUIET, label, new_figure

TAPS = (1 / 16, 1 / 4, 3 / 8, 1 / 4, 1 / 16)
SIZE = 17


def atrous_figure():
    fig = new_figure(10.0, 3.8, panels=3)[0]
    colour_map = __import__("matplotlib").colormaps["Blues"]
    for level, ax in enumerate(fig.axes):
        step = 2 ** level
        centre = SIZE // 2
        for y in range(SIZE):
            for x in range(SIZE):
                ax.add_patch(Rectangle((x, y), 1, 1, fill=False, color=QUIET, lw=0.3))
        for j in range(5):
            for k in range(5):
                weight = TAPS[j] * TAPS[k]
                x, y = centre + (k - 2) * step, centre + (j - 2) * step
                ax.add_patch(Rectangle((x, y), 1, 1, color=colour_map(0.25 + 0.75 * weight / TAPS[2] ** 2)))
        ax.add_patch(Rectangle((centre, centre), 1, 1, fill=False, color="black", lw=1.5))
        ax.add_patch(Rectangle((0, 0), SIZE, SIZE, fill=False, color=SURFACE, lw=1))
        ax.set_xlim(-0.5, SIZE + 0.5)
        ax.set_ylim(-2.5, SIZE + 0.5)
        label(ax, (SIZE / 2, -1.3), f"taps {step} pixel{'s' if step > 1 else ''} apart, "
                                    f"reach {4 * step + 1} × {4 * step + 1}", fontsize=9)
        ax.set_title(f"level {level}")
    return fig


def edge_stopping_term(d2, s2):
    """One guide's factor of w(p, q): exp(−d² / s²)."""
    return math.exp(-d2 / s2)


def edge_stopping_figure():
    fig = new_figure(11.0, 3.0, panels=4)[0]
    # Each guide: its title, the difference plotted, d² of that difference, s² of a σ, the default σ, the
    # first guess (None: none), and the x range.
    guides = (
        ("colour", "|c_p − c_q| / √(Var_p + Var_q)", lambda x: x * x, lambda s: s * s, 2.0, None, 6.0),
        ("normal", "angle between n_p and n_q (degrees)", lambda x: 2 - 2 * math.cos(math.radians(x)),
         lambda s: s * s, 1.0, 0.3, 180.0),
        ("depth", "|z_p − z_q| / max(z_p, z_q)", lambda x: x * x, lambda s: s * s, 0.2, 0.05, 1.0),
        ("albedo", "|a_p − a_q|", lambda x: x * x, lambda s: s * s, 0.3, 0.1, 1.0),
    )
    symbols = {"colour": "σ_c", "normal": "σ_n", "depth": "σ_z", "albedo": "σ_a"}
    for ax, (name, difference, d2, s2, default, first_guess, reach) in zip(fig.axes, guides):
        ax.set_aspect("auto")
        ax.axis("on")
        xs = [reach * i / 300 for i in range(301)]
        ax.plot(xs, [edge_stopping_term(d2(x), s2(default)) for x in xs], color=RAY, lw=2,
                label=f"{symbols[name]} = {default:g} (default)")
        if first_guess is not None:
            ax.plot(xs, [edge_stopping_term(d2(x), s2(first_guess)) for x in xs], color=ACCENT, lw=1.6,
                    ls="--", label=f"{symbols[name]} = {first_guess:g} (first guess)")
        ax.set_xlim(0, reach)
        ax.set_ylim(0, 1.05)
        ax.set_xlabel(difference, fontsize=8)
        ax.legend(fontsize=7, frameon=False, loc="upper right")
        ax.set_title(name)
    for ax in fig.axes[1:]:
        ax.tick_params(labelleft=False)
    for ax in fig.axes[2:]:
        ax.set_xticks([0, 0.5, 1], labels=["0", "0.5", "1"])
    fig.axes[1].set_xticks([0, 45, 90, 135, 180])
    colour = fig.axes[0]
    colour.set_ylabel("weight of q in p")
    # Two noisy estimates of one colour differ by about one unit: the default lets them mix.
    noise_weight = edge_stopping_term(1.0, 2.0 ** 2)
    colour.plot([1, 1], [0, noise_weight], color=QUIET, lw=1, ls=":")
    colour.plot(1, noise_weight, "o", color=QUIET, ms=4)
    label(colour, (2.5, 0.6), f"noise alone:\n|c_p − c_q|² ≈\nVar_p + Var_q,\nweight {noise_weight:.2f} at 1",
          color=QUIET, fontsize=7, ha="left")
    return fig


def figures():
    return {"10_denoising/images/diagram_atrous.svg": atrous_figure(),
            "10_denoising/images/diagram_edge_stopping.svg": edge_stopping_figure()}
