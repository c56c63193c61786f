"""Chapter 01: the pinhole camera seen from the side, its film at distance 1, a ray through each pixel
centre, and a pixel's stratified jittered points (pixel_sampling.hpp); the thin lens (camera.hpp,
thin_lens_ray) and its disk of confusion, and the concentric map (concentric_disk.hpp)."""

import math
import random

from figure_style import LIGHT, QUIET, RAY, SURFACE, ACCENT, arrow, label, new_figure

FILM_ROWS = 6
VFOV_DEGREES = 50.0


def film_height(py: float) -> float:
    """The film's height of a point py pixels from its top: (1 − 2 py / H) · tan(vfov / 2)."""
    half_height = math.tan(math.radians(VFOV_DEGREES) / 2)
    return (1 - 2 * py / FILM_ROWS) * half_height


def figures():
    fig, (side, pixel) = new_figure(9.0, 3.6, panels=2)
    # Side view: the eye e at the origin looking along w (to the right), the film at distance 1.
    top, bottom = film_height(0), film_height(FILM_ROWS)
    side.plot([1, 1], [bottom, top], color=SURFACE, lw=2)
    for row in range(FILM_ROWS + 1):
        side.plot([0.97, 1.03], [film_height(row)] * 2, color=SURFACE, lw=1)
    side.plot(0, 0, "o", color="black")
    label(side, (-0.12, 0), "e", ha="right")
    arrow(side, (0, 0), (0.45, 0), color=QUIET, width=1)
    label(side, (0.45, -0.07), "w", color=QUIET)
    arrow(side, (0, 0), (0, 0.45), color=QUIET, width=1)
    label(side, (-0.07, 0.45), "v", color=QUIET)
    label(side, (1.0, bottom - 0.15), "film, at distance 1", fontsize=9)
    for row in range(FILM_ROWS):
        y = film_height(row + 0.5)
        side.plot([0, 2.4], [0, 2.4 * y], color=RAY, lw=1)
    label(side, (1.6, 1.25), "a ray through\neach pixel centre", ha="left", color=RAY, fontsize=9)
    side.annotate("", xy=(1.12, top), xytext=(1.12, 0), arrowprops=dict(arrowstyle="<->", color=ACCENT))
    label(side, (1.17, 0.5 * top), "tan(vfov/2)", color=ACCENT, ha="left", fontsize=9)
    side.set_xlim(-0.3, 2.6)
    side.set_ylim(-1.3, 1.4)
    side.set_title("the pinhole camera, from the side")

    # One pixel: 16 stratified jittered points, one per cell of a 4 × 4 grid.
    n = 4
    rng = random.Random(1)
    pixel.plot([0, 1, 1, 0, 0], [0, 0, 1, 1, 0], color=SURFACE, lw=2)
    for k in range(1, n):
        pixel.plot([k / n, k / n], [0, 1], color=QUIET, lw=0.6, ls=":")
        pixel.plot([0, 1], [k / n, k / n], color=QUIET, lw=0.6, ls=":")
    for i in range(n * n):
        x = (i % n + rng.random()) / n
        y = (i // n + rng.random()) / n
        pixel.plot(x, y, "o", color=RAY, ms=4)
    pixel.plot(0.5, 0.5, "x", color=LIGHT, ms=9, mew=2)
    label(pixel, (0.5, -0.1), "x = centre: one point, aliased", color=LIGHT, fontsize=9)
    label(pixel, (0.5, 1.1), "stratified jitter: (x + (i mod n + u₁)/n, y + (⌊i/n⌋ + u₂)/n)", fontsize=9)
    pixel.set_xlim(-0.2, 1.2)
    pixel.set_ylim(-0.25, 1.25)
    pixel.set_title("one pixel, 16 rays")
    return {"01_ray_generation/images/diagram_camera.svg": fig,
            "01_ray_generation/images/diagram_thin_lens.svg": thin_lens_figure()}


APERTURE = 0.5
FOCUS_DISTANCE = 4.0


def confusion_radius(z: float) -> float:
    """The disk of confusion at depth z: aperture · |1 − z / focus_distance| (lesson 01, "A thin lens")."""
    return APERTURE * abs(1 - z / FOCUS_DISTANCE)


def concentric_disk(a: float, b: float) -> tuple[float, float]:
    """Shirley and Chiu's map of (a, b) in [−1, 1]² to the unit disk."""
    if a == 0 and b == 0:
        return 0.0, 0.0
    if abs(a) > abs(b):
        r, phi = a, math.pi / 4 * (b / a)
    else:
        r, phi = b, math.pi / 2 - math.pi / 4 * (a / b)
    return r * math.cos(phi), r * math.sin(phi)


def thin_lens_figure():
    fig, (side, disk) = new_figure(9.0, 3.6, panels=2)
    # Side view: the lens at x = 0 (height 2 · aperture), the plane in focus at x = focus_distance.
    side.plot([0, 0], [-APERTURE, APERTURE], color=SURFACE, lw=3)
    label(side, (0, -APERTURE - 0.25), "lens, radius = aperture", fontsize=9)
    focus_height = 0.6
    side.plot([FOCUS_DISTANCE] * 2, [-1.3, 1.3], color=QUIET, lw=1, ls=":")
    label(side, (FOCUS_DISTANCE, -1.5), "plane in focus", color=QUIET, fontsize=9)
    side.plot(FOCUS_DISTANCE, focus_height, "o", color=ACCENT)
    label(side, (FOCUS_DISTANCE + 0.15, focus_height + 0.2), "f", color=ACCENT, ha="left")
    far = 6.5
    for lens_y in (-APERTURE, 0.0, APERTURE):
        # Each ray leaves o = eye + aperture · (x u + y v) and passes through f.
        slope = (focus_height - lens_y) / FOCUS_DISTANCE
        side.plot([0, far], [lens_y, lens_y + slope * far], color=RAY, lw=1)
    for z, name in ((2.0, "z = 2"), (far, "z = 6.5")):
        centre = focus_height * z / FOCUS_DISTANCE
        r = confusion_radius(z)
        side.plot([z, z], [centre - r, centre + r], color=LIGHT, lw=3)
        label(side, (z, centre + r + 0.25), f"{name}: r = {r:.3g}", color=LIGHT, fontsize=9)
    side.set_xlim(-0.5, 7.2)
    side.set_ylim(-1.7, 2.3)
    side.set_title("rays of one film point meet at f; elsewhere they spread")

    # The concentric map: rings and spokes of the square go to circles and radii of the disk.
    for k in range(1, 5):
        s = k / 4
        square = [(-s, -s), (s, -s), (s, s), (-s, s), (-s, -s)]
        edge = [(x0 + (x1 - x0) * t / 32, y0 + (y1 - y0) * t / 32)
                for (x0, y0), (x1, y1) in zip(square, square[1:]) for t in range(33)]
        xs, ys = zip(*(concentric_disk(a, b) for a, b in edge))
        disk.plot([x + 2.6 for x in xs], ys, color=RAY, lw=1)
        disk.plot([a for a, _ in square], [b for _, b in square], color=RAY, lw=1)
    for a, b in ((1, 1), (1, -1), (0.6, 1), (-0.3, 1)):
        disk.plot([0, a], [0, b], color=LIGHT, lw=1)
        x, y = concentric_disk(a, b)
        disk.plot([2.6, 2.6 + x], [0, y], color=LIGHT, lw=1)
    arrow(disk, (1.15, 0), (1.45, 0), color=SURFACE)
    label(disk, (0, -1.3), "(a, b) = 2u − 1", fontsize=9)
    label(disk, (2.6, -1.3), "r = a, φ = (π/4)(b/a)\nwhere |a| > |b|", fontsize=9)
    disk.set_xlim(-1.2, 3.8)
    disk.set_ylim(-1.7, 1.3)
    disk.set_title("the concentric map: square to lens disk")
    return fig
