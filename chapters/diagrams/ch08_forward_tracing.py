"""Chapter 08: a light path and its connections to a pinhole camera. Each vertex of a path from the light is
joined to the pinhole by a shadow ray; where it passes, it lands on one film pixel and adds the path's
weight times the camera's importance there. A connection the block stops adds nothing."""

from matplotlib.patches import Rectangle

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


def figures():
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
    return {"08_forward_tracing/images/diagram_light_paths.svg": fig}
