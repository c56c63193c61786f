"""Chapter 02: the ray–sphere roots, the barycentric coordinates of a triangle and the slab test of a box,
each computed from its equation; and a BVH built by splitting a set of shapes in halves."""

import math
import random

from matplotlib.patches import Circle, Polygon, Rectangle

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, arrow, label, new_figure


def sphere_roots(o, d, c, r):
    """t₀ ≤ t₁ of |o + t d − c|² = r² for a unit d, in the stable form: q = −b − sign(b)·√Δ, t = c₀/q and q."""
    f = (o[0] - c[0], o[1] - c[1])
    b = f[0] * d[0] + f[1] * d[1]
    c0 = f[0] ** 2 + f[1] ** 2 - r * r
    q = -b - math.copysign(math.sqrt(b * b - c0), b)
    return sorted((c0 / q, q))


def point(o, d, t):
    return (o[0] + t * d[0], o[1] + t * d[1])


def area(a, b, c):
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))


def shapes_figure():
    fig, (sphere_ax, triangle_ax, slab_ax) = new_figure(11.0, 3.8, panels=3)
    # Ray–sphere: both roots of the quadratic on the ray.
    o, c, r = (-2.0, -0.6), (1.0, 0.0), 1.0
    d = (1.0, 0.25)
    length = math.hypot(*d)
    d = (d[0] / length, d[1] / length)
    t0, t1 = sphere_roots(o, d, c, r)
    sphere_ax.add_patch(Circle(c, r, fill=False, color=SURFACE, lw=1.5))
    sphere_ax.plot(*c, "+", color=QUIET)
    arrow(sphere_ax, o, point(o, d, t1 + 1.0))
    label(sphere_ax, (o[0], o[1] - 0.25), "o")
    for t, name in ((t0, "t₀"), (t1, "t₁")):
        p = point(o, d, t)
        sphere_ax.plot(*p, "o", color=ACCENT)
        label(sphere_ax, (p[0], p[1] + 0.25), f"{name} = {t:.2f}", color=ACCENT, fontsize=9)
    label(sphere_ax, (0.5, -1.55), "|o + t d − c|² = r²:\nt² + 2 b t + c₀ = 0", fontsize=9)
    sphere_ax.set_xlim(-2.3, 3.3)
    sphere_ax.set_ylim(-1.9, 1.5)
    sphere_ax.set_title("ray–sphere: two roots")

    # Barycentric coordinates: each is the area of the sub-triangle opposite its vertex, over the whole.
    p0, p1, p2 = (0.0, 0.0), (3.0, 0.3), (1.2, 2.4)
    p = (1.5, 0.9)
    whole = area(p0, p1, p2)
    b = (area(p, p1, p2) / whole, area(p0, p, p2) / whole, area(p0, p1, p) / whole)
    colours = ("#f4d9a8", "#bcd3f0", "#d5e8c4")
    for sub, colour in zip(((p, p1, p2), (p0, p, p2), (p0, p1, p)), colours):
        triangle_ax.add_patch(Polygon(sub, closed=True, facecolor=colour, edgecolor=SURFACE, lw=0.8))
    for v, name, offset in ((p0, "p₀", (-0.2, -0.15)), (p1, "p₁", (0.2, -0.15)), (p2, "p₂", (0, 0.2))):
        label(triangle_ax, (v[0] + offset[0], v[1] + offset[1]), name)
    triangle_ax.plot(*p, "o", color=ACCENT)
    label(triangle_ax, (p[0] + 0.15, p[1] + 0.12), "p", color=ACCENT, ha="left")
    centres = ((p[0] + p1[0] + p2[0]) / 3, (p[1] + p1[1] + p2[1]) / 3), \
              ((p0[0] + p[0] + p2[0]) / 3, (p0[1] + p[1] + p2[1]) / 3), \
              ((p0[0] + p1[0] + p[0]) / 3, (p0[1] + p1[1] + p[1]) / 3)
    for i, centre in enumerate(centres):
        label(triangle_ax, centre, f"b{'₀₁₂'[i]}={b[i]:.2f}", fontsize=8)
    label(triangle_ax, (1.5, -0.6), "p = b₀ p₀ + b₁ p₁ + b₂ p₂,  b₀ + b₁ + b₂ = 1", fontsize=9)
    triangle_ax.set_xlim(-0.4, 3.4)
    triangle_ax.set_ylim(-0.9, 2.8)
    triangle_ax.set_title("a triangle: barycentrics as areas")

    # The slab test: per axis the interval of t inside the slab; the box is their intersection.
    lo, hi = (1.0, 0.5), (2.5, 1.6)
    o, d = (0.0, 0.0), (1.0, 0.55)
    t_x = sorted(((lo[0] - o[0]) / d[0], (hi[0] - o[0]) / d[0]))
    t_y = sorted(((lo[1] - o[1]) / d[1], (hi[1] - o[1]) / d[1]))
    t_enter, t_exit = max(t_x[0], t_y[0]), min(t_x[1], t_y[1])
    slab_ax.axvspan(lo[0], hi[0], color=RAY, alpha=0.08)
    slab_ax.axhspan(lo[1], hi[1], color=LIGHT, alpha=0.12)
    slab_ax.add_patch(Rectangle(lo, hi[0] - lo[0], hi[1] - lo[1], fill=False, color=SURFACE, lw=1.5))
    arrow(slab_ax, o, point(o, d, 3.3), color=QUIET, width=1)
    slab_ax.plot(*zip(point(o, d, t_x[0]), point(o, d, t_x[1])), color=RAY, lw=5, alpha=0.5)
    slab_ax.plot(*zip(point(o, d, t_y[0]), point(o, d, t_y[1])), color=LIGHT, lw=3, alpha=0.8)
    slab_ax.plot(*zip(point(o, d, t_enter), point(o, d, t_exit)), color=ACCENT, lw=2)
    label(slab_ax, (1.75, 2.25), "x slab", color=RAY, fontsize=9)
    label(slab_ax, (3.3, 1.05), "y slab", color=LIGHT, fontsize=9, ha="left")
    label(slab_ax, (1.6, -0.45), f"t_enter = max({t_x[0]:.2f}, {t_y[0]:.2f}) = {t_enter:.2f}\n"
                                 f"t_exit = min({t_x[1]:.2f}, {t_y[1]:.2f}) = {t_exit:.2f}",
          color=ACCENT, fontsize=9)
    slab_ax.set_xlim(-0.2, 3.9)
    slab_ax.set_ylim(-0.9, 2.4)
    slab_ax.set_title("the slab test: a box is three slabs")
    return fig


def bvh_nodes(points, depth):
    """(box, depth) of every node of a BVH over `points`, split at the median of the longer axis."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    box = (min(xs) - 0.12, min(ys) - 0.12, max(xs) + 0.12, max(ys) + 0.12)
    nodes = [(box, depth)]
    if len(points) > 6:
        axis = 0 if box[2] - box[0] >= box[3] - box[1] else 1
        ordered = sorted(points, key=lambda p: p[axis])
        half = len(ordered) // 2
        nodes += bvh_nodes(ordered[:half], depth + 1) + bvh_nodes(ordered[half:], depth + 1)
    return nodes


def bvh_figure():
    rng = random.Random(4)
    clusters = ((1.0, 1.0), (4.0, 1.5), (2.5, 3.5))
    points = [(cx + rng.gauss(0, 0.5), cy + rng.gauss(0, 0.4)) for cx, cy in clusters for _ in range(8)]
    fig, (ax,) = new_figure(5.0, 4.0)
    colours = (SURFACE, ACCENT, RAY, LIGHT, QUIET)
    for (x0, y0, x1, y1), depth in bvh_nodes(points, 0):
        ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, color=colours[min(depth, 4)],
                               lw=2.4 - 0.5 * depth))
    for p in points:
        ax.add_patch(Circle(p, 0.1, color=SURFACE))
    o, d = (-0.5, 4.6), (1.0, -0.55)
    arrow(ax, o, (o[0] + 6.2 * d[0], o[1] + 6.2 * d[1]), color=RAY)
    label(ax, (2.6, -0.5), "each level splits its shapes in two halves;\n"
                           "a ray visits only the boxes it crosses", fontsize=9)
    ax.set_xlim(-0.7, 5.8)
    ax.set_ylim(-1.0, 5.0)
    ax.set_title("a bounding volume hierarchy")
    return fig


def figures():
    return {"02_intersection/images/diagram_shapes.svg": shapes_figure(),
            "02_intersection/images/diagram_bvh.svg": bvh_figure()}
