"""Chapter 01: the pinhole camera seen from the side, its film at distance 1, a ray through each pixel
centre, and a pixel's stratified jittered points (pixel_sampling.hpp)."""

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
    return {"01_ray_generation/images/diagram_camera.svg": fig}
