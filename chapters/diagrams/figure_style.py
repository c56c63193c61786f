"""What every course diagram shares: the figure, its colours, arrows and labels, and a deterministic SVG.

The SVG is the same bytes on every run: ids come from a fixed salt (svg.hashsalt), no date is written, and
text stays text (svg.fonttype "none"), so no font's glyph outlines are embedded.
"""

from __future__ import annotations

import io

import matplotlib
from matplotlib.figure import Figure

matplotlib.rcParams.update({
    "svg.hashsalt": "ray-tracing-course",
    "svg.fonttype": "none",
    "font.family": "DejaVu Sans",
    "font.size": 10,
    "axes.titlesize": 11,
    "savefig.bbox": "tight",
})

RAY = "#1f5fbf"        # rays from the camera
LIGHT = "#d08a00"      # light and what comes from it
SURFACE = "#444444"    # surfaces, boxes, the film
ACCENT = "#c0392b"     # what the figure points at
QUIET = "#9a9a9a"      # construction lines


def new_figure(width: float, height: float, panels: int = 1) -> tuple[Figure, list]:
    """A figure of `panels` side-by-side axes with equal scales and no frame (a drawing, not a plot)."""
    fig = Figure(figsize=(width, height))
    axes = [fig.add_subplot(1, panels, i + 1) for i in range(panels)]
    for ax in axes:
        ax.set_aspect("equal")
        ax.axis("off")
    return fig, axes


def arrow(ax, start, end, color=RAY, width=1.4, style="-|>", dashed=False):
    """An arrow from start to end (points in data units)."""
    ax.annotate("", xy=end, xytext=start,
                arrowprops=dict(arrowstyle=style, color=color, lw=width, shrinkA=0, shrinkB=0,
                                linestyle="--" if dashed else "-"))


def label(ax, at, text, color="black", **kwargs):
    ax.text(at[0], at[1], text, color=color, ha=kwargs.pop("ha", "center"), va=kwargs.pop("va", "center"),
            **kwargs)


def svg_bytes(fig: Figure) -> bytes:
    """The figure as SVG bytes, with no date in it."""
    out = io.BytesIO()
    fig.savefig(out, format="svg", metadata={"Date": None})
    return out.getvalue()
