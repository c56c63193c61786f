"""Chapter 11: the threads of a warp diverging. Each lane traces one path; Russian roulette ends the paths
after different numbers of bounces, but the warp runs in lock step until its longest path ends, the
finished lanes masked off. The share of lanes doing work is the warp's efficiency.
And chapter 02's BVH as the shaders read it: the nodes depth first, an interior node's first child the next
node and `offset` its second, a leaf's `offset` and `count` a run of primitive slots in leaf order
(bvh.cpp's builder, gpu_scene.cpp's upload, scene.glsl's search)."""

import random

from matplotlib.patches import FancyBboxPatch, Rectangle

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, arrow, label, new_figure

LANES = 8
SURVIVAL = 0.7


def path_lengths(seed=11):
    """Bounces of each lane's path: one at least, then each further one with probability SURVIVAL."""
    rng = random.Random(seed)
    lengths = []
    for _ in range(LANES):
        n = 1
        while rng.random() < SURVIVAL:
            n += 1
        lengths.append(n)
    return lengths


def warp_divergence_figure():
    lengths = path_lengths()
    steps = max(lengths)
    fig, (ax,) = new_figure(8.0, 3.6)
    for lane, n in enumerate(lengths):
        y = LANES - 1 - lane
        for step in range(steps):
            active = step < n
            ax.add_patch(Rectangle((step, y), 0.92, 0.8, color=RAY if active else QUIET,
                                   alpha=0.85 if active else 0.25, hatch=None if active else "///"))
        label(ax, (-0.2, y + 0.4), f"lane {lane}", ha="right", fontsize=8)
    for step in range(steps):
        label(ax, (step + 0.46, -0.35), f"{step + 1}", fontsize=8)
    label(ax, (steps / 2, -0.9), "bounce (the warp executes every step for all its lanes)", fontsize=9)
    efficiency = sum(lengths) / (LANES * steps)
    label(ax, (steps + 0.3, LANES / 2), f"busy: {sum(lengths)} of {LANES * steps}\nlane-steps = "
                                        f"{efficiency:.0%}", ha="left", color=ACCENT, fontsize=10)
    ax.set_xlim(-1.5, steps + 3.2)
    ax.set_ylim(-1.2, LANES + 0.2)
    ax.set_title("a warp of 8 lanes: paths of different lengths (roulette, survival 0.7)")
    return fig


# A small tree: a leaf is its number of primitives, an interior node the pair of its children.
TREE = ((3, 2), (4, (2, 3)))


def flatten(tree):
    """The nodes as bvh.cpp's builder lays them out: depth first, each node (offset, count, depth, children)
    with an interior node's first child right after it and its second at `offset`, a leaf's primitives the
    next `count` slots."""
    nodes, slots = [], [0]

    def place(subtree, depth):
        index = len(nodes)
        nodes.append(None)
        if isinstance(subtree, int):
            nodes[index] = (slots[0], subtree, depth, ())
            slots[0] += subtree
            return index
        first = place(subtree[0], depth + 1)
        second = place(subtree[1], depth + 1)
        nodes[index] = (second, 0, depth, (first, second))
        return index

    place(tree, 0)
    return nodes, slots[0]


def bvh_layout_figure():
    nodes, primitive_count = flatten(TREE)
    fig, (ax,) = new_figure(10.0, 5.6)
    # The tree: leaves spread evenly in depth-first order, an interior node above the middle of its children.
    leaves = [i for i, node in enumerate(nodes) if node[1] > 0]
    at = {}
    for i in reversed(range(len(nodes))):
        offset, count, depth, children = nodes[i]
        x = 1.5 + 11 * leaves.index(i) / (len(leaves) - 1) if count else sum(at[c][0] for c in children) / 2
        at[i] = (x, 10.5 - 1.1 * depth)
    for i, (offset, count, depth, children) in enumerate(nodes):
        for child in children:
            ax.plot(*zip(at[i], at[child]), color=QUIET, lw=1, zorder=1)
    for i, (offset, count, depth, children) in enumerate(nodes):
        colour = LIGHT if count else RAY
        ax.add_patch(FancyBboxPatch((at[i][0] - 0.3, at[i][1] - 0.25), 0.6, 0.5, boxstyle="round,pad=0.05",
                                    color=colour, alpha=0.9, zorder=2))
        label(ax, at[i], str(i), color="white", fontsize=9, zorder=3)
        if count:
            label(ax, (at[i][0], at[i][1] - 0.5), f"{count} primitives", color=LIGHT, fontsize=7)

    # The node array: index, offset, count; arcs from an interior node to its second child.
    cell, left, top = 1.3, 1.2, 4.6
    label(ax, (left - 0.2, top + 0.3), "nodes[i]", ha="right", fontsize=8)
    label(ax, (left - 0.2, top - 0.25), "offset", ha="right", fontsize=8)
    label(ax, (left - 0.2, top - 0.75), "count", ha="right", fontsize=8)
    for i, (offset, count, depth, children) in enumerate(nodes):
        x = left + i * cell
        colour = LIGHT if count else RAY
        ax.add_patch(Rectangle((x, top - 1.0), cell, 1.0, fill=True, color=colour, alpha=0.18, lw=0))
        ax.add_patch(Rectangle((x, top - 1.0), cell, 1.0, fill=False, color=SURFACE, lw=1))
        label(ax, (x + cell / 2, top + 0.3), str(i), fontsize=9)
        label(ax, (x + cell / 2, top - 0.25), str(offset), fontsize=9)
        label(ax, (x + cell / 2, top - 0.75), str(count), fontsize=9)
        if not count:
            ax.annotate("", xy=(left + (offset + 0.5) * cell, top + 0.55), xytext=(x + cell / 2, top + 0.55),
                        arrowprops=dict(arrowstyle="-|>", color=ACCENT, lw=1.2, shrinkA=0, shrinkB=0,
                                        connectionstyle="arc3,rad=-0.35"))
            arrow(ax, (x + cell * 0.7, top - 1.15), (x + cell * 1.3, top - 1.15), color=RAY, width=1.2)
    label(ax, (left + len(nodes) * cell + 0.2, top + 0.9), "second child:\noffset", color=ACCENT, fontsize=8,
          ha="left")
    label(ax, (left + len(nodes) * cell + 0.2, top - 1.15), "first child: i + 1", color=RAY, fontsize=8,
          ha="left")

    # The primitive slots in leaf order: each leaf's run of `count` slots from `offset`.
    slot, bottom = 0.8, 1.4
    label(ax, (left - 0.2, bottom + 0.3), "primitives", ha="right", fontsize=8)
    for s in range(primitive_count):
        ax.add_patch(Rectangle((left + s * slot, bottom), slot, 0.6, fill=False, color=SURFACE, lw=1))
        label(ax, (left + (s + 0.5) * slot, bottom + 0.3), str(s), fontsize=8)
    for i in leaves:
        offset, count = nodes[i][:2]
        x0, x1 = left + offset * slot + 0.12, left + (offset + count) * slot - 0.12
        ax.plot([x0, x1], [bottom - 0.15, bottom - 0.15], color=LIGHT, lw=3)
        label(ax, ((x0 + x1) / 2, bottom - 0.45), f"leaf {i}", color=LIGHT, fontsize=8)
        ax.plot([left + (i + 0.5) * cell, (x0 + x1) / 2], [top - 1.0, bottom + 0.6], color=LIGHT, lw=0.8,
                ls="--")
    label(ax, (7.0, 0.2), "the walk at interior node i: test the boxes of nodes i + 1 and offset, go on to the nearer "
                          "one hit,\npush the other with its entry distance; pop, skipping what lies beyond the "
                          "nearest hit so far", fontsize=8)
    ax.set_xlim(-0.6, 15.0)
    ax.set_ylim(-0.3, 11.0)
    ax.set_title("chapter 02's BVH as the shader reads it: 32-byte nodes, depth first")
    return fig


def figures():
    return {"11_gpu_shaders/images/diagram_warp_divergence.svg": warp_divergence_figure(),
            "11_gpu_shaders/images/diagram_bvh_layout.svg": bvh_layout_figure()}
