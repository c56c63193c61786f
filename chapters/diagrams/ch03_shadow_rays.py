"""Chapter 03: shadow acne. The computed hit point lies within its error box, on either side of the surface;
a shadow ray started there may meet its own surface. The robust offset moves it by δ = Σ |n_i| e_i along n
(ray_offset.hpp), just out of the box. And why no fixed ε does that at every scale: against the scene's scale,
ε must stay above the error bound of p and below the scene's smallest gap."""

import math

from matplotlib.patches import Rectangle

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, arrow, label, new_figure


def offset_figure():
    fig, (ax,) = new_figure(7.0, 3.8)
    # A surface y = 0.35 x tilted, normal n; the error box e (exaggerated) around the computed point.
    slope = 0.35
    norm = (1 + slope * slope) ** 0.5
    n = (-slope / norm, 1 / norm)
    ax.plot([-2.5, 2.5], [-2.5 * slope, 2.5 * slope], color=SURFACE, lw=2)
    ax.fill_between([-2.5, 2.5], [-2.5 * slope, 2.5 * slope], [-1.6, -1.6], color=SURFACE, alpha=0.08)
    label(ax, (2.3, 2.3 * slope - 0.35), "surface", color=SURFACE, fontsize=9)
    e = (0.6, 0.45)
    exact = (0.0, 0.0)
    computed = (0.25, -0.3)  # rounded to a point just below the surface
    ax.add_patch(Rectangle((computed[0] - e[0], computed[1] - e[1]), 2 * e[0], 2 * e[1], fill=False,
                           color=QUIET, ls="--"))
    label(ax, (computed[0] - e[0] - 0.05, computed[1] - e[1] - 0.12), "|p − p_exact| ≤ e", color=QUIET,
          fontsize=8, ha="left")
    ax.plot(*exact, "o", color=QUIET, ms=4)
    ax.plot(*computed, "o", color=ACCENT)
    label(ax, (computed[0] + 0.12, computed[1] - 0.08), "p", color=ACCENT, ha="left")
    # Light up and to the left; the ray from p crosses the surface at a tiny t: acne.
    light = (-1.8, 2.2)
    ax.plot(*light, "*", color=LIGHT, ms=16)
    label(ax, (light[0] + 0.15, light[1] + 0.1), "light", color=LIGHT, ha="left")
    d = (light[0] - computed[0], light[1] - computed[1])
    # Where p + t d meets y = slope · x: the self-intersection.
    t_self = (slope * computed[0] - computed[1]) / (d[1] - slope * d[0])
    self_hit = (computed[0] + t_self * d[0], computed[1] + t_self * d[1])
    arrow(ax, computed, (computed[0] + 0.25 * d[0], computed[1] + 0.25 * d[1]), color=ACCENT, dashed=True)
    ax.plot(*self_hit, "x", color=ACCENT, ms=9, mew=2)
    label(ax, (self_hit[0] - 0.3, self_hit[1] + 0.2), f"hits itself at t = {t_self:.3f}", color=ACCENT,
          ha="right", fontsize=9)
    # The robust offset: δ = |n_x| e_x + |n_y| e_y along n.
    delta = abs(n[0]) * e[0] + abs(n[1]) * e[1]
    moved = (computed[0] + delta * n[0], computed[1] + delta * n[1])
    arrow(ax, computed, moved, color=SURFACE, width=1.2)
    ax.plot(*moved, "o", color=RAY)
    label(ax, (moved[0] + 0.12, moved[1] + 0.05), "p + δ n,  δ = |n_x| e_x + |n_y| e_y", color=RAY,
          ha="left", fontsize=9)
    arrow(ax, moved, (moved[0] + 0.85 * (light[0] - moved[0]), moved[1] + 0.85 * (light[1] - moved[1])),
          color=RAY)
    label(ax, (-0.2, 1.6), "reaches the light", color=RAY, fontsize=9, ha="left")
    ax.set_xlim(-2.8, 3.6)
    ax.set_ylim(-1.4, 2.6)
    ax.set_title("shadow acne, and the offset that avoids it")
    return fig


GAMMA_5 = 5 * 2.0 ** -24 / (1 - 5 * 2.0 ** -24)   # gamma_bound(5), float's unit roundoff 2⁻²⁴
EPSILON = 1e-4                                    # the fixed offset (epsilon_offset's default)
TOP = 1.2                                         # the blue sphere's top, y = c_y + r = 0.6 + 0.6 (ch03_default)
GAP = 0.01                                        # the slab floats 0.01 above the floor
STUDY_SCALES = (1e-3, 1.0, 1e3, 1e5)


def epsilon_scale_figure():
    """At the top of the blue sphere scaled by s: its error bound δ = γ₅ (|c_y| + r) s (n = y, so the robust
    offset is δ), half a float ulp of its y, and the slab's gap 0.01 s, against the fixed ε."""
    fig, (ax,) = new_figure(7.0, 3.6)
    ax.set_aspect("auto")
    ax.axis("on")
    scales = [10 ** (k / 4) for k in range(-20, 33)]
    delta = [GAMMA_5 * TOP * s for s in scales]
    gap = [GAP * s for s in scales]
    # Half an ulp of y = TOP s is 2^(k − 24) for y in [2^k, 2^(k+1)): a staircase, one step per power of two.
    steps = range(math.floor(math.log2(TOP * scales[0])), math.ceil(math.log2(TOP * scales[-1])))
    ax.step([2.0 ** k / TOP for k in steps], [2.0 ** (k - 24) for k in steps], where="post", color=QUIET,
            lw=1, label="half an ulp of p_y: p + ε n rounds back to p below it")
    ax.fill_between(scales, [1e-12] * len(scales), delta, color=ACCENT, alpha=0.12)
    ax.fill_between(scales, gap, [1e8] * len(scales), color=LIGHT, alpha=0.12)
    ax.plot(scales, delta, color=ACCENT, lw=2, label="error bound δ = γ₅ (|c_y| + r) s: the robust offset")
    ax.plot(scales, gap, color=LIGHT, lw=2, label="the slab's gap 0.01 s: an offset above it leaks")
    ax.axhline(EPSILON, color=RAY, lw=2, ls="--", label=f"fixed ε = {EPSILON:g}")
    for s in STUDY_SCALES:
        ax.axvline(s, color=SURFACE, lw=0.6, ls=":")
    low, high = GAP ** -1 * EPSILON, EPSILON / (GAMMA_5 * TOP)
    ax.text(math.sqrt(low * high), 3e-4, f"ε works for\n{low:g} < s < {high:.0f}", color=RAY, fontsize=8,
            ha="center", va="bottom")
    ax.text(3e-2, 1e-11, "below δ: acne", color=ACCENT, fontsize=8)
    ax.text(3e-5, 1e1, "above the gap:\nlight leaks", color=LIGHT, fontsize=8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(scales[0], scales[-1])
    ax.set_ylim(1e-12, 1e5)
    ax.set_xlabel("scene scale s (dotted: the study's 1e-3, 1, 1e3, 1e5)")
    ax.set_ylabel("distance along n (scene units)")
    ax.legend(fontsize=7, frameon=False, loc="lower right")
    ax.set_title("no fixed ε fits every scale; δ follows the scale")
    return fig


def figures():
    return {"03_shadow_rays/images/diagram_offset.svg": offset_figure(),
            "03_shadow_rays/images/diagram_epsilon_scale.svg": epsilon_scale_figure()}
