"""Chapter 12: the directional quadtree. The sphere cut into bands of equal height in z = cos θ and sectors
of equal φ has cells of equal solid angle (dω = dz dφ), so the square (u, v) = ((z + 1) / 2, φ / 2π) holds
directions with the constant Jacobian 4π (equal_area_map.hpp). On that square, a quadtree refined as
directional_quadtree.cpp refines it: energy recorded from a lobe of light, max(0, cos)^8 about one
direction, three rounds of record and refine with ρ = 0.01; each leaf shaded by its density.
And the one-sample mixture of guided_vertex.cpp on a slice through the hemisphere: light through a gap, the
BSDF's cosine density, a guide refined as the quadtree is (in one dimension), their mixture, and the weights
f cos / p that each gives."""

import math
import random

from matplotlib.figure import Figure
from matplotlib.patches import Rectangle

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, label, new_figure

LOBE = (0.71, 0.35, 0.61)  # about the direction of the tests' lobe, normalised
THRESHOLD = 0.01
MAX_DEPTH = 9


def direction(u, v):
    z = 2 * u - 1
    r = math.sqrt(max(0.0, 1 - z * z))
    return (r * math.cos(2 * math.pi * v), r * math.sin(2 * math.pi * v), z)


def lobe_weight(w):
    return max(0.0, sum(a * b for a, b in zip(w, LOBE))) ** 8


class Node:
    """A square [x, x + size) × [y, y + size) of the map: its energy and, split, its four quadrants."""

    def __init__(self, x, y, size):
        self.x, self.y, self.size = x, y, size
        self.energy = 0.0
        self.children = None

    def leaves(self):
        if self.children is None:
            return [self]
        return [leaf for child in self.children for leaf in child.leaves()]


def record(root, points):
    for u, v, weight in points:
        node = root
        while True:
            node.energy += weight
            if node.children is None:
                break
            half = node.size / 2
            node = node.children[(u >= node.x + half) + 2 * (v >= node.y + half)]


def refined(old, total, depth=0):
    """The new tree: a square splits where its share of the energy exceeds the threshold."""
    new = Node(old.x, old.y, old.size)
    new.energy = old.energy
    if depth < MAX_DEPTH and (depth == 0 or old.energy > THRESHOLD * total):
        half = old.size / 2
        children = old.children or []
        new.children = []
        for q in range(4):
            x, y = old.x + half * (q % 2), old.y + half * (q // 2)
            source = children[q] if children else Node(x, y, half)
            if not children:
                source.energy = old.energy / 4
            new.children.append(refined(source, total, depth + 1))
    return new


def trained_tree():
    rng = random.Random(12)
    tree = refined(Node(0.0, 0.0, 1.0), 1.0)
    for _ in range(3):
        recording = empty_copy(tree)
        points = [(u, v, lobe_weight(direction(u, v))) for u, v in ((rng.random(), rng.random()) for _ in range(20000))]
        record(recording, points)
        tree = refined(recording, recording.energy)
    return tree


def empty_copy(node):
    copy = Node(node.x, node.y, node.size)
    if node.children is not None:
        copy.children = [empty_copy(child) for child in node.children]
    return copy


def quadtree_figure():
    fig = new_figure(10.0, 4.2, panels=2)[0]
    sphere, square = fig.axes
    # The sphere seen from the side: bands of equal height in z, equal area.
    t = [2 * math.pi * i / 200 for i in range(201)]
    sphere.plot([math.cos(a) for a in t], [math.sin(a) for a in t], color=SURFACE)
    for k in range(1, 8):
        z = -1 + 2 * k / 8
        r = math.sqrt(1 - z * z)
        sphere.plot([-r, r], [z, z], color=QUIET, lw=0.8)
    sphere.plot([-1.25, -1.25], [-1, 1], color=RAY, lw=2)
    label(sphere, (-1.55, 0), "z = cos θ", rotation=90, fontsize=9)
    label(sphere, (0, -1.25), "bands of equal height: equal area (Archimedes)", fontsize=9)
    sphere.set_title("dω = dz dφ")
    tree = trained_tree()
    leaves = tree.leaves()
    densities = [leaf.energy / max(1e-12, tree.energy) / (leaf.size * leaf.size) for leaf in leaves]
    top = max(densities)
    colour_map = __import__("matplotlib").colormaps["Blues"]
    for leaf, density in zip(leaves, densities):
        square.add_patch(Rectangle((leaf.x, leaf.y), leaf.size, leaf.size, facecolor=colour_map(0.05 + 0.95 * math.sqrt(density / top)),
                                   edgecolor=SURFACE, lw=0.3))
    square.add_patch(Rectangle((0, 0), 1, 1, fill=False, color=SURFACE, lw=1))
    u, v = (LOBE[2] + 1) / 2, (math.atan2(LOBE[1], LOBE[0]) % (2 * math.pi)) / (2 * math.pi)
    square.plot([u], [v], "o", color=ACCENT, ms=5)
    label(square, (0.5, -0.07), "u = (cos θ + 1) / 2 →", fontsize=9)
    label(square, (-0.07, 0.5), "v = φ / 2π →", rotation=90, fontsize=9)
    square.set_title(f"the quadtree after 3 passes: {len(leaves)} leaves")
    return fig


GAP_ANGLE, GAP_WIDTH, FLOOR = math.radians(35), math.radians(4), 0.03  # light through a gap, and a dim room
ALPHA = 0.5  # the guided vertex's share of guided draws


def slice_integrand(theta):
    """f L_i cos on the slice (a diffuse f): the gap's narrow peak over the room's dim light."""
    return (FLOOR + math.exp(-0.5 * ((theta - GAP_ANGLE) / GAP_WIDTH) ** 2)) * math.cos(theta)


def refined_bins(lo, hi, total, depth=0):
    """The 1-D quadtree: a bin splits while it holds more than 1 % of the energy (ρ of the quadtree)."""
    energy = integral(slice_integrand, lo, hi)
    if depth >= 7 or energy <= THRESHOLD * total:
        return [(lo, hi, energy)]
    mid = (lo + hi) / 2
    return refined_bins(lo, mid, total, depth + 1) + refined_bins(mid, hi, total, depth + 1)


def integral(f, lo, hi, steps=200):
    h = (hi - lo) / steps
    return sum(f(lo + (i + 0.5) * h) for i in range(steps)) * h


def mixture_figure():
    fig = Figure(figsize=(10.0, 3.8))
    densities, weights = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    half = math.pi / 2
    thetas = [-half + math.pi * (i + 0.5) / 600 for i in range(600)]
    total = integral(slice_integrand, -half, half, 2000)
    bins = refined_bins(-half, half, total)

    def guide(theta):
        return next(e / (hi - lo) / total for lo, hi, e in bins if lo <= theta < hi)

    def bsdf(theta):
        return math.cos(theta) / 2

    def mixture(theta):
        return ALPHA * guide(theta) + (1 - ALPHA) * bsdf(theta)

    degrees = [math.degrees(t) for t in thetas]
    ideal = [slice_integrand(t) / total for t in thetas]
    densities.fill_between(degrees, ideal, color=LIGHT, alpha=0.35, lw=0, label="ideal: f L cos, normalised")
    densities.plot(degrees, [bsdf(t) for t in thetas], color=QUIET, ls="--", label="BSDF: cos θ")
    densities.plot(degrees, [guide(t) for t in thetas], color=RAY, lw=1, label=f"guide: {len(bins)} bins")
    densities.plot(degrees, [mixture(t) for t in thetas], color=ACCENT, lw=1.6, label=f"mixture, α = {ALPHA}")
    densities.set_yscale("log")
    densities.set_ylim(0.005, 20)
    densities.set_xlabel("θ (degrees), a slice through the hemisphere")
    densities.set_title("densities over θ")
    densities.legend(fontsize=8, loc="upper left", frameon=False)
    for name, p, style in (("BSDF alone", bsdf, dict(color=QUIET, ls="--")),
                           ("mixture", mixture, dict(color=ACCENT, lw=1.6))):
        weights.plot(degrees, [slice_integrand(t) / total / p(t) for t in thetas], label=name, **style)
    weights.axhline(1, color=SURFACE, lw=0.6)
    weights.set_yscale("log")
    weights.set_xlabel("θ (degrees)")
    weights.set_title("weight f L cos / p: flat at 1 is noise-free")
    weights.legend(fontsize=8, loc="upper left", frameon=False)
    return fig


def figures():
    return {"12_path_guiding/images/diagram_quadtree.svg": quadtree_figure(),
            "12_path_guiding/images/diagram_one_sample_mis.svg": mixture_figure()}
