"""Chapter 05: a path as a recursion. A camera ray meets x₁; the radiance leaving x₁ is its emission plus
the light arriving from one sampled direction, which is the same question asked again at x₂, and so on
until a light or the stopping rule ends it. Then Russian roulette in the furnace (albedo ρ everywhere): from
depth d₀ a path goes on with probability q = min(1, max β) and then β ← β / q (termination.cpp), so fewer
paths go deeper but each survivor weighs more, and the mean stays ρᵏ."""

from matplotlib.patches import Rectangle

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, arrow, label, new_figure


def path_figure():
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
    return fig


ALBEDO = 0.8          # the furnace's ρ
ROULETTE_START = 3    # --roulette-start's default d₀
DEPTHS = 16


def roulette_by_depth():
    """For depth k = 0 … DEPTHS: the fraction of paths still alive and a survivor's throughput β."""
    alive, weight = [1.0], [1.0]
    for k in range(DEPTHS):
        q = 1.0 if k < ROULETTE_START else min(1.0, weight[-1])   # survival_probability
        alive.append(alive[-1] * q)
        weight.append(ALBEDO * weight[-1] / q)
    return alive, weight


def roulette_figure():
    fig, (ax,) = new_figure(7.0, 3.6)
    ax.set_aspect("auto")
    ax.axis("on")
    depths = list(range(DEPTHS + 1))
    alive, weight = roulette_by_depth()
    ax.plot(depths, [ALBEDO ** k for k in depths], color=SURFACE, lw=2,
            label="without roulette: every path goes on, β = ρᵏ")
    ax.plot(depths, alive, "o-", color=ACCENT, ms=4, lw=1.2, label="with roulette: fraction of paths alive")
    ax.plot(depths, weight, "s-", color=RAY, ms=4, lw=1.2, label="with roulette: a survivor's β, weighted by 1/q")
    ax.plot(depths, [a * w for a, w in zip(alive, weight)], "x", color=LIGHT, ms=8, mew=2,
            label="with roulette: mean = alive × β = ρᵏ")
    ax.axvline(ROULETTE_START, color=QUIET, ls=":")
    ax.text(ROULETTE_START + 0.2, 0.025, f"roulette starts, d₀ = {ROULETTE_START}", color=QUIET, fontsize=8)
    ax.set_yscale("log")
    ax.set_ylim(0.02, 12)
    ax.set_xlabel("depth k (bounces)")
    ax.set_ylabel("fraction / throughput")
    ax.legend(fontsize=8, frameon=False, loc="upper right")
    ax.set_title(f"Russian roulette in the furnace, ρ = {ALBEDO}: q = min(1, β)")
    return fig


def figures():
    return {"05_recursive_gi/images/diagram_path.svg": path_figure(),
            "05_recursive_gi/images/diagram_roulette.svg": roulette_figure()}
