"""Chapter 05: a path as a recursion. A camera ray meets x₁; the radiance leaving x₁ is its emission plus
the light arriving from one sampled direction, which is the same question asked again at x₂, and so on
until a light or the stopping rule ends it."""

from matplotlib.patches import Rectangle

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, arrow, label, new_figure


def figures():
    fig, (ax,) = new_figure(9.0, 4.2)
    ax.add_patch(Rectangle((0, 0), 1, 1, fill=False, color=SURFACE, lw=2))
    ax.plot([0.4, 0.6], [1, 1], color=LIGHT, lw=6)
    label(ax, (0.5, 1.07), "light: Lₑ", color=LIGHT, fontsize=9)
    camera = (-0.45, 0.55)
    vertices = [camera, (0.35, 0.0), (1.0, 0.45), (0.52, 1.0)]
    ax.plot(*camera, "s", color="black", ms=8)
    label(ax, (camera[0], camera[1] + 0.09), "camera x₀")
    for i, (a, b) in enumerate(zip(vertices, vertices[1:])):
        arrow(ax, a, b, color=RAY if i == 0 else ACCENT)
    for i, (v, offset) in enumerate(zip(vertices[1:], ((0, -0.08), (0.08, 0), (0.06, -0.07))), start=1):
        ax.plot(*v, "o", color="black", ms=5)
        label(ax, (v[0] + offset[0], v[1] + offset[1]), f"x{'₁₂₃'[i - 1]}", fontsize=10)
    text = ("L(x₁→x₀) = Lₑ(x₁) + f(x₁) L(x₂→x₁) cos θ₁ / p(ω₁)\n"
            "L(x₂→x₁) = Lₑ(x₂) + f(x₂) L(x₃→x₂) cos θ₂ / p(ω₂)\n"
            "L(x₃→x₂) = Lₑ(x₃)     (the path meets the light)\n\n"
            "trace(ray, depth):\n"
            "    hit = nearest(ray);  if none: return 0\n"
            "    ω, f, p = sample(hit)\n"
            "    return Lₑ(hit)\n"
            "         + f · trace(ray(hit, ω), depth + 1) · cos θ / p")
    label(ax, (1.12, 0.5), text, ha="left", fontsize=8, family="DejaVu Sans Mono")
    label(ax, (0.5, -0.12), "one sampled direction per bounce: the path", color=QUIET, fontsize=9)
    ax.set_xlim(-0.6, 3.6)
    ax.set_ylim(-0.2, 1.15)
    ax.set_title("a path is the recursion unrolled")
    return {"05_recursive_gi/images/diagram_path.svg": fig}
