"""The course's extension points (common/README.md, "The material model and the path loop"): each interface,
the chapter that defines it, and what each later chapter implements, one row an interface."""

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, label, new_figure

COLUMNS = ["02", "04", "06", "07", "08", "09", "10", "11"]

# (interface, where it is defined, {chapter: what that chapter implements or adds})
ROWS = [
    ("Light", "04 light.hpp", {
        "04": "Quad, Triangle, Sphere,\nPoint, Distant, Spot\nEmitter",
        "08": "emission by\nclass", "11": "GPU record\nby class"}),
    ("MaterialKind\n(scene keys)", "common io/\nmaterial_kind.hpp;\nthe six types: io/\ncourse_materials.cpp", {
        "04": "a test's own\n'matte' type"}),
    ("Bsdf +\nMaterialModel", "04 bsdf.hpp,\nmaterial_hooks.hpp", {
        "04": "Lambert, Mirror,\nGlossy, Retro", "07": "Smooth/Rough\nDielectric,\nConductor",
        "11": "exporter\nby class"}),
    ("Medium", "04 medium.hpp", {
        "07": "Absorbing\n(Beer–Lambert)", "09": "Homogeneous\n(scattering)"}),
    ("path extension\nsegment, crosses,\nvertex, seen, survives", "06 path_tracer.hpp", {
        "06": "SurfacePaths,\nBsdfVertex", "09": "VolumePathTracer,\nPhaseVertex", "11": "the loop\nin GLSL"}),
    ("PathObserver", "06 path_observer.hpp", {
        "08": "CameraCaustic\nCut", "10": "PathFeatures"}),
    ("World / BVH", "02 world.hpp", {
        "02": "shapes, BVH,\nwide BVH", "11": "nodes\nflattened"}),
]


def figures():
    fig, (ax,) = new_figure(13.0, 8.2)
    x0, dx, dy = 3.6, 1.25, 1.05
    label(ax, (0.6, 0.7), "interface", fontsize=10, weight="bold")
    label(ax, (2.35, 0.7), "defined in", fontsize=10, weight="bold")
    label(ax, (x0 + 3.5 * dx, 1.15), "what each chapter implements", fontsize=10)
    for j, chapter in enumerate(COLUMNS):
        label(ax, (x0 + j * dx, 0.7), chapter, fontsize=10, weight="bold")
    for i, (name, where, impls) in enumerate(ROWS):
        y = -i * dy
        ax.plot([-0.2, x0 + (len(COLUMNS) - 0.4) * dx], [y - dy / 2] * 2, color=QUIET, lw=0.5)
        label(ax, (0.6, y), name, color=RAY, fontsize=9, weight="bold")
        label(ax, (2.35, y), where, color=SURFACE, fontsize=8)
        defined = where.split()[0]
        for j, chapter in enumerate(COLUMNS):
            if chapter in impls:
                colour = ACCENT if chapter == defined else LIGHT
                label(ax, (x0 + j * dx, y), impls[chapter], color=colour, fontsize=7.5)
    label(ax, (x0 + 3 * dx, -len(ROWS) * dy + 0.05),
          "red: implemented where the interface is defined;  orange: a later chapter adds by implementing",
          color=SURFACE, fontsize=8.5)
    ax.set_xlim(-0.3, x0 + len(COLUMNS) * dx - 0.3)
    ax.set_ylim(-len(ROWS) * dy - 0.2, 1.4)
    ax.set_aspect("auto")
    return {"../common/images/diagram_interfaces.svg": fig}
