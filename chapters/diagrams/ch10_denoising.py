"""Chapter 10: the à-trous kernel. Level i filters with the 5 × 5 B3-spline h_j h_k, h = (1, 4, 6, 4, 1)/16,
its taps 2^i pixels apart (the holes): three levels reach 17 × 17 pixels with 25 taps each (atrous.hpp)."""

from matplotlib.patches import Rectangle

from figure_style import SURFACE, QUIET, label, new_figure

TAPS = (1 / 16, 1 / 4, 3 / 8, 1 / 4, 1 / 16)
SIZE = 17


def figures():
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
    return {"10_denoising/images/diagram_atrous.svg": fig}
