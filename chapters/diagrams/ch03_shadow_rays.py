"""Chapter 03: shadow acne. The computed hit point lies within its error box, on either side of the surface;
a shadow ray started there may meet its own surface. The robust offset moves it by δ = Σ |n_i| e_i along n
(ray_offset.hpp), just out of the box."""

from matplotlib.patches import Rectangle

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, arrow, label, new_figure


def figures():
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
    return {"03_shadow_rays/images/diagram_offset.svg": fig}
