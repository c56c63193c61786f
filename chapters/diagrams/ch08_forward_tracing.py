"""Chapter 08: a light path and its connections to a pinhole camera. Each vertex of a path from the light is
joined to the pinhole by a shadow ray; where it passes, it lands on one film pixel and adds the path's
weight times the camera's importance there. A connection the block stops adds nothing.
And the pinhole's importance across the film: a pixel of film area A_pix at angle θ_c from the view lies
1/cos θ_c away and is tilted by θ_c, so it subtends dω = cos³θ_c dA_film; We = 1 / (A_pix cos⁴θ_c) makes
We cos θ_c dω = dA_film / A_pix, the same for every pixel (pinhole_importance)."""

import math

from matplotlib.patches import Arc, Polygon, Rectangle

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, arrow, label, new_figure

PINHOLE = (-0.35, 0.5)
FILM_X = -0.6
BLOCK = (0.55, 0.0, 0.8, 0.35)  # x0, y0, x1, y1


def segment_hits_box(a, b, box):
    """Whether the segment a→b crosses the box (the slab test of chapter 02, in 2D)."""
    t0, t1 = 0.0, 1.0
    for axis in (0, 1):
        d = b[axis] - a[axis]
        lo, hi = box[axis], box[axis + 2]
        if abs(d) < 1e-12:
            if not lo <= a[axis] <= hi:
                return False
            continue
        ta, tb = sorted(((lo - a[axis]) / d, (hi - a[axis]) / d))
        t0, t1 = max(t0, ta), min(t1, tb)
    return t0 <= t1


HALF_FOV_DEGREES = 50.0  # the 100° film of the test "The pinhole importance integrates to 1 over a pixel"
FILM_PIXELS = 8          # across the half-height tan 50° · 2, in the side view


def light_paths_figure():
    fig, (ax,) = new_figure(7.0, 4.2)
    ax.add_patch(Rectangle((0, 0), 1, 1, fill=False, color=SURFACE, lw=2))
    ax.add_patch(Rectangle(BLOCK[:2], BLOCK[2] - BLOCK[0], BLOCK[3] - BLOCK[1], color=SURFACE, alpha=0.35))
    ax.plot([0.4, 0.6], [1, 1], color=LIGHT, lw=6)
    path = [(0.5, 1.0), (0.25, 0.0), (1.0, 0.62), (0.8, 1.0), (0.9, 0.0)]
    for a, b in zip(path, path[1:]):
        arrow(ax, a, b, color=LIGHT)
    label(ax, (0.5, 1.08), "light y₀", color=LIGHT, fontsize=9)
    ax.plot([FILM_X, FILM_X], [0.2, 0.8], color=SURFACE, lw=3)
    label(ax, (FILM_X, 0.13), "film", fontsize=9)
    ax.plot(*PINHOLE, "o", color="black")
    label(ax, (PINHOLE[0], PINHOLE[1] + 0.08), "pinhole", fontsize=9)
    for i, vertex in enumerate(path[1:], start=1):
        ax.plot(*vertex, "o", color="black", ms=4)
        blocked = segment_hits_box(vertex, PINHOLE, BLOCK)
        if blocked:
            ax.plot(*zip(vertex, PINHOLE), color=ACCENT, ls=":", lw=1.2)
            continue
        # Through the pinhole to the film: the pixel this connection adds to.
        s = (FILM_X - vertex[0]) / (PINHOLE[0] - vertex[0])
        on_film = (FILM_X, vertex[1] + s * (PINHOLE[1] - vertex[1]))
        ax.plot(*zip(vertex, on_film), color=RAY, ls="--", lw=1)
        ax.plot(*on_film, "s", color=RAY, ms=5)
    labels = {1: (0.2, -0.07), 2: (1.07, 0.62), 3: (0.84, 1.07), 4: (0.93, -0.07)}
    for i, at in labels.items():
        label(ax, at, f"y{'₀₁₂₃₄'[i]}", fontsize=9)
    label(ax, (0.45, -0.2), "dashed: a connection that reaches a pixel;\ndotted: one the block stops",
          color=QUIET, fontsize=8)
    ax.set_xlim(-0.75, 1.2)
    ax.set_ylim(-0.32, 1.15)
    ax.set_title("tracing from the light, connecting to the camera")
    return fig


def importance_figure():
    fig, (side, curves) = new_figure(10.0, 3.9, panels=2)
    # Side view: the eye at the origin looking along w (to the right), the film at distance 1, equal pixels.
    half = math.tan(math.radians(HALF_FOV_DEGREES))
    edges = [-half + 2 * half * k / FILM_PIXELS for k in range(FILM_PIXELS + 1)]
    side.plot([1, 1], [-half, half], color=SURFACE, lw=2)
    for y in edges:
        side.plot([0, 1], [0, y], color=QUIET, lw=0.5)
        side.plot([0.97, 1.03], [y, y], color=SURFACE, lw=1)
    for lo, hi, colour in ((edges[FILM_PIXELS // 2], edges[FILM_PIXELS // 2 + 1], RAY),
                           (edges[-2], edges[-1], ACCENT)):
        side.add_patch(Polygon([(0, 0), (1, lo), (1, hi)], color=colour, alpha=0.3, lw=0))
        spread = math.degrees(math.atan(hi) - math.atan(lo))
        label(side, (1.08, (lo + hi) / 2), f"{spread:.1f}°", color=colour, ha="left", fontsize=9)
    theta_edge = math.atan((edges[-2] + edges[-1]) / 2)
    side.add_patch(Arc((0, 0), 0.7, 0.7, theta1=0, theta2=math.degrees(theta_edge), color=ACCENT))
    label(side, (0.52, 0.21), "θ_c", color=ACCENT, fontsize=9)
    side.plot([0, 1], [0, 0], color=QUIET, lw=1, ls="--")
    label(side, (0.55, -0.1), "w", color=QUIET, fontsize=9)
    label(side, (0.22, 0.62), "1 / cos θ_c", color=ACCENT, fontsize=9, rotation=math.degrees(theta_edge))
    side.plot(0, 0, "o", color="black")
    label(side, (-0.06, 0), "eye", ha="right", fontsize=9)
    label(side, (0.55, -half - 0.2), f"{FILM_PIXELS} pixels of equal film width, a {2 * HALF_FOV_DEGREES:.0f}° film",
          fontsize=9)
    side.set_xlim(-0.3, 1.5)
    side.set_ylim(-half - 0.35, half + 0.1)
    side.set_title("equal pixels, smaller angles off the axis")

    # The factors of We cos θ_c dω against θ_c, on a log scale: they multiply to 1.
    curves.set_aspect("auto")
    curves.axis("on")
    degrees = [i * 0.5 for i in range(int(2 * HALF_FOV_DEGREES) + 1)]
    cosines = [math.cos(math.radians(d)) for d in degrees]
    curves.plot(degrees, [c ** 3 for c in cosines], color=RAY, lw=2, label="dω / dA_film = cos³θ_c")
    curves.plot(degrees, cosines, color=QUIET, lw=1.4, ls=":", label="cos θ_c of the measurement")
    curves.plot(degrees, [c ** -4 for c in cosines], color=ACCENT, lw=2, label="A_pix We = 1 / cos⁴θ_c")
    curves.plot(degrees, [1.0] * len(degrees), color=LIGHT, lw=2, ls="--",
                label="A_pix We cos θ_c dω / dA_film = 1")
    curves.set_yscale("log", base=2)
    curves.set_yticks([0.25, 0.5, 1, 2, 4, 8], labels=["1/4", "1/2", "1", "2", "4", "8"])
    curves.set_xlim(0, HALF_FOV_DEGREES)
    curves.set_xlabel("θ_c, the angle from the view direction (degrees)")
    curves.set_ylabel("factor (log scale)")
    curves.legend(fontsize=8, frameon=False, loc="upper left")
    curves.set_title("the importance undoes the cos³ and the cos")
    return fig


def figures():
    return {"08_forward_tracing/images/diagram_light_paths.svg": light_paths_figure(),
            "08_forward_tracing/images/diagram_pinhole_importance.svg": importance_figure()}
