"""Chapter 07: Snell's law with Fresnel's split (arrow widths are the exact R and T at η = 1.5), the exact
Fresnel reflectance against Schlick's approximation entering and leaving glass (total internal reflection
past the critical angle), and a rough surface's microfacet half-vector h = (ωᵢ + ωₒ)/|ωᵢ + ωₒ|. Then
Beer–Lambert in the coloured-glass scene: T = exp(−σ_a d) per colour, and the colour white light keeps."""

import math

from matplotlib.patches import Rectangle

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, arrow, label, new_figure

ETA = 1.5


def fresnel(cos_i, eta_i, eta_t):
    """The exact unpolarised reflectance of a dielectric interface (1 past the critical angle)."""
    sin_t = eta_i / eta_t * math.sqrt(max(0.0, 1 - cos_i * cos_i))
    if sin_t >= 1:
        return 1.0
    cos_t = math.sqrt(1 - sin_t * sin_t)
    r_par = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t)
    r_perp = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t)
    return (r_par ** 2 + r_perp ** 2) / 2


def schlick(cos_i, eta_i, eta_t):
    """R₀ + (1 − R₀)(1 − cos)⁵ with the cosine on the less dense side (1 past the critical angle)."""
    r0 = ((eta_t - eta_i) / (eta_t + eta_i)) ** 2
    if eta_i > eta_t:
        sin_t = eta_i / eta_t * math.sqrt(max(0.0, 1 - cos_i * cos_i))
        if sin_t >= 1:
            return 1.0
        cos_i = math.sqrt(1 - sin_t * sin_t)
    return r0 + (1 - r0) * (1 - cos_i) ** 5


def snell_panel(ax):
    theta_i = math.radians(55)
    theta_t = math.asin(math.sin(theta_i) / ETA)
    r = fresnel(math.cos(theta_i), 1.0, ETA)
    ax.fill_between([-1.3, 1.3], [0, 0], [-1.2, -1.2], color=RAY, alpha=0.08)
    ax.plot([-1.3, 1.3], [0, 0], color=SURFACE, lw=1.5)
    ax.plot([0, 0], [-1.1, 1.1], color=QUIET, ls=":")
    arrow(ax, (-math.sin(theta_i), math.cos(theta_i)), (0, 0), color="black", width=2.5)
    arrow(ax, (0, 0), (math.sin(theta_i), math.cos(theta_i)), color=LIGHT, width=0.5 + 8 * r)
    arrow(ax, (0, 0), (math.sin(theta_t), -math.cos(theta_t)), color=RAY, width=0.5 + 2.5 * (1 - r))
    label(ax, (-0.62, 0.95), f"θᵢ = {math.degrees(theta_i):.0f}°", fontsize=9)
    label(ax, (0.9, 0.85), f"R = {r:.3f}", color=LIGHT, fontsize=9)
    label(ax, (0.95, -0.55), f"T = {1 - r:.3f}\nθₜ = {math.degrees(theta_t):.1f}°", color=RAY, fontsize=9)
    label(ax, (-0.95, 0.15), "air, η = 1", fontsize=8, color=QUIET)
    label(ax, (-0.95, -0.15), "glass, η = 1.5", fontsize=8, color=QUIET)
    label(ax, (0, -1.3), "sin θₜ = sin θᵢ / η", fontsize=9)
    ax.set_xlim(-1.35, 1.35)
    ax.set_ylim(-1.45, 1.2)
    ax.set_title("Snell and Fresnel")


def fresnel_panel(ax):
    ax.set_aspect("auto")
    ax.axis("on")
    angles = [i * 0.25 for i in range(361)]
    cosines = [math.cos(math.radians(a)) for a in angles]
    for eta_i, eta_t, colour, name in ((1.0, ETA, LIGHT, "entering"), (ETA, 1.0, RAY, "leaving")):
        ax.plot(angles, [fresnel(c, eta_i, eta_t) for c in cosines], color=colour, lw=2, label=f"exact, {name}")
        ax.plot(angles, [schlick(c, eta_i, eta_t) for c in cosines], color=colour, lw=1, ls="--",
                label=f"Schlick, {name}")
    critical = math.degrees(math.asin(1 / ETA))
    ax.axvline(critical, color=QUIET, ls=":")
    ax.text(critical + 1, 0.55, f"critical angle\n{critical:.1f}°: total\ninternal reflection", fontsize=8)
    ax.set_xlabel("angle of incidence θᵢ (degrees)")
    ax.set_ylabel("reflectance R")
    ax.legend(fontsize=7, frameon=False, loc="upper left")
    ax.set_title("how much reflects, η = 1.5")


def microfacet_panel(ax):
    # A zig-zag of microfacets; ωᵢ and ωₒ fixed; the facet whose normal is h reflects ωᵢ into ωₒ.
    xs = [-1.2 + 0.3 * k for k in range(9)]
    ys = [0.12 if k % 2 else 0.0 for k in range(9)]
    ax.plot(xs, ys, color=SURFACE, lw=1.5)
    ax.plot([-1.3, 1.3], [-0.05, -0.05], color=QUIET, ls=":")
    wi = (-math.sin(math.radians(50)), math.cos(math.radians(50)))
    wo = (math.sin(math.radians(20)), math.cos(math.radians(20)))
    h = (wi[0] + wo[0], wi[1] + wo[1])
    length = math.hypot(*h)
    h = (h[0] / length, h[1] / length)
    base = (0.15, 0.06)
    facet = (-h[1] * 0.22, h[0] * 0.22)  # the facet through base whose normal is h
    ax.plot([base[0] - facet[0], base[0] + facet[0]], [base[1] - facet[1], base[1] + facet[1]], color=ACCENT, lw=3)
    arrow(ax, (base[0] + wi[0], base[1] + wi[1]), base, color="black")
    arrow(ax, base, (base[0] + wo[0], base[1] + wo[1]), color=LIGHT)
    arrow(ax, base, (base[0] + 0.8 * h[0], base[1] + 0.8 * h[1]), color=ACCENT, width=2)
    arrow(ax, base, (base[0], base[1] + 0.7), color=QUIET, width=1)
    label(ax, (base[0] + wi[0] - 0.08, base[1] + wi[1] + 0.05), "ωᵢ")
    label(ax, (base[0] + wo[0] + 0.1, base[1] + wo[1] + 0.05), "ωₒ", color=LIGHT)
    label(ax, (base[0] + 0.8 * h[0] - 0.12, base[1] + 0.8 * h[1] + 0.08), "h", color=ACCENT)
    label(ax, (base[0] + 0.1, base[1] + 0.72), "n", color=QUIET)
    label(ax, (0, -0.35), "h = (ωᵢ + ωₒ) / |ωᵢ + ωₒ|:\nonly facets with normal h send ωᵢ to ωₒ;\n"
                          "D(h) says how many there are (GGX)", fontsize=8)
    ax.set_xlim(-1.3, 1.3)
    ax.set_ylim(-0.6, 1.25)
    ax.set_title("rough glass: the half-vector")


ABSORPTION = (0.0005, 0.004, 0.01)   # σ_a of ch07_coloured_glass.json, per unit length
DIAMETER = 180                       # the sphere's: a path through its centre
GREEN = "#2e8b57"                    # the green channel's curve (the palette has no green)


def beer_lambert_figure():
    fig, (ax,) = new_figure(7.0, 3.6)
    ax.set_aspect("auto")
    ax.axis("on")
    distances = [i * 2 for i in range(181)]
    for sigma, colour, name in zip(ABSORPTION, (ACCENT, GREEN, RAY), ("red", "green", "blue")):
        ax.plot(distances, [math.exp(-sigma * d) for d in distances], color=colour, lw=2,
                label=f"{name}, σ_a = {sigma:g}")
        kept = math.exp(-sigma * DIAMETER)
        ax.plot(DIAMETER, kept, "o", color=colour)
        ax.text(DIAMETER + 5, kept + 0.02, f"{kept:.0%}", color=colour, fontsize=9)
    ax.axvline(DIAMETER, color=QUIET, ls=":")
    ax.text(DIAMETER - 5, 0.76, "through the sphere's\ncentre, d = 180", color=QUIET, fontsize=8, ha="right")
    # The colour white light keeps after d: the three transmittances as an RGB swatch.
    step = distances[1] - distances[0]
    for d in distances[:-1]:
        ax.add_patch(Rectangle((d, -0.16), step, 0.1, lw=0,
                               color=tuple(math.exp(-sigma * (d + step / 2)) for sigma in ABSORPTION)))
    label(ax, (distances[-1] / 2, -0.21), "the colour white light keeps", color=SURFACE, fontsize=8)
    ax.set_xlim(0, distances[-1])
    ax.set_ylim(-0.25, 1.05)
    ax.set_xlabel("distance d travelled inside the glass")
    ax.set_ylabel("transmittance T = exp(−σ_a d)")
    ax.legend(fontsize=8, frameon=False, loc="center right", bbox_to_anchor=(1.0, 0.68))
    ax.set_title("Beer–Lambert: coloured glass turns amber")
    return fig


def figures():
    fig = new_figure(12.0, 3.8, panels=3)[0]
    snell_panel(fig.axes[0])
    fresnel_panel(fig.axes[1])
    microfacet_panel(fig.axes[2])
    return {"07_bsdf_refraction/images/diagram_snell_fresnel.svg": fig,
            "07_bsdf_refraction/images/diagram_beer_lambert.svg": beer_lambert_figure()}
