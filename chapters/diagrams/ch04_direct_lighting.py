"""Chapter 04: the solid angle of a small patch, dω = A cos θ / r², and the four BRDFs' lobes, f(ωᵢ) cos θᵢ
for light leaving towards ωₒ at 45° (brdf.cpp: Lambert ρ/π, the normalised lobe ρ (e + 2)/(2π) cosᵉ α around
the mirror direction or around ωₒ itself, and the mirror's single direction). Then a light's area density
turned into a solid-angle one: uniform points on a ceiling quad seen from p, and pdf_ω = d² / (cos θ_l A)
along it against the spherical rectangle's 1/Ω (area_to_solid_angle_pdf, spherical_rectangle.hpp)."""

import math

from matplotlib.patches import Arc, Polygon

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, arrow, label, new_figure


def lobe(axis_angle, exponent, theta):
    """The normalised lobe (e + 2)/(2π) cosᵉ α, α the angle between θ and the axis (in the plane)."""
    c = math.cos(theta - axis_angle)
    return (exponent + 2) / (2 * math.pi) * c ** exponent if c > 0 else 0.0


def solid_angle_panel(ax):
    ax.add_patch(Arc((0, 0), 2, 2, theta1=0, theta2=180, color=QUIET, ls="--"))
    label(ax, (-0.9, 0.2), "unit\nsphere", color=QUIET, fontsize=8)
    ax.plot(0, 0, "o", color="black")
    label(ax, (0, -0.15), "x")
    # A patch of width A at distance r, its normal tilted by θ from the direction back to x.
    r, width, tilt = 2.6, 0.9, math.radians(40)
    direction = math.radians(60)
    centre = (r * math.cos(direction), r * math.sin(direction))
    along = (math.cos(direction + math.pi / 2 + tilt), math.sin(direction + math.pi / 2 + tilt))
    a = (centre[0] - width / 2 * along[0], centre[1] - width / 2 * along[1])
    b = (centre[0] + width / 2 * along[0], centre[1] + width / 2 * along[1])
    ax.plot(*zip(a, b), color=LIGHT, lw=4)
    for end in (a, b):
        ax.plot([0, end[0]], [0, end[1]], color=QUIET, lw=0.8)
    angles = sorted(math.atan2(end[1], end[0]) for end in (a, b))
    ax.add_patch(Arc((0, 0), 2, 2, theta1=math.degrees(angles[0]), theta2=math.degrees(angles[1]),
                     color=ACCENT, lw=4))
    normal = (-math.cos(direction + tilt), -math.sin(direction + tilt))
    arrow(ax, centre, (centre[0] + 0.6 * normal[0], centre[1] + 0.6 * normal[1]), color=LIGHT, width=1)
    label(ax, (centre[0] + 0.55, centre[1] + 0.25), "area A", color=LIGHT, fontsize=9, ha="left")
    label(ax, (1.5, -0.45), f"dω = A cos θ / r²  (r = {r}, θ = 40°)", color=ACCENT, fontsize=9)
    ax.set_xlim(-1.3, 3.6)
    ax.set_ylim(-0.7, 3.2)
    ax.set_title("solid angle of a small patch")


def lobes_panel(ax):
    out_angle = math.radians(45)          # ωₒ, from the normal
    mirror = -out_angle                   # the mirror direction of ωₒ
    thetas = [math.radians(-90 + i * 0.5) for i in range(361)]
    curves = (("Lambert  ρ/π", lambda t: 1 / math.pi, SURFACE),
              ("glossy, e = 20, around the mirror direction", lambda t: lobe(mirror, 20, t), RAY),
              ("retro-reflective, e = 20, around ωₒ", lambda t: lobe(out_angle, 20, t), LIGHT))
    for name, f, colour in curves:
        radius = [0.6 * f(t) * math.cos(t) for t in thetas]  # f cos θ, drawn as a radius
        ax.plot([r * math.sin(t) for r, t in zip(radius, thetas)],
                [r * math.cos(t) for r, t in zip(radius, thetas)], color=colour, lw=1.6, label=name)
    ax.plot([-1.3, 1.3], [0, 0], color=SURFACE, lw=2)
    arrow(ax, (0, 0), (1.1 * math.sin(out_angle), 1.1 * math.cos(out_angle)), color="black", width=1.2)
    label(ax, (1.2 * math.sin(out_angle), 1.2 * math.cos(out_angle)), "ωₒ")
    arrow(ax, (0, 0), (1.1 * math.sin(mirror), 1.1 * math.cos(mirror)), color=ACCENT, width=1.2)
    label(ax, (1.25 * math.sin(mirror), 1.22 * math.cos(mirror)), "mirror:\none direction", color=ACCENT,
          fontsize=8)
    ax.add_patch(Polygon([(-1.3, 0), (1.3, 0), (1.3, -0.08), (-1.3, -0.08)], color=SURFACE, alpha=0.2))
    ax.legend(loc="lower center", bbox_to_anchor=(0.5, -0.32), fontsize=8, frameon=False)
    ax.set_xlim(-1.4, 1.4)
    ax.set_ylim(-0.1, 1.4)
    ax.set_title("f(ωᵢ) cos θᵢ for each BRDF")


HEIGHT = 1.0                  # the quad light: a ceiling at y = HEIGHT above p, facing down,
LIGHT_X = (-0.5, 2.5)         # x from -0.5 to 2.5 (the cross-section drawn),
LIGHT_Z = (-0.5, 0.5)         # z from -0.5 to 0.5: area A = 3
AREA = (LIGHT_X[1] - LIGHT_X[0]) * (LIGHT_Z[1] - LIGHT_Z[0])
SAMPLES = 12


def area_pdf_to_solid_angle(x):
    """pdf_ω = d² / (cos θ_l A) of the light point (x, HEIGHT, 0) seen from p at the origin."""
    d = math.hypot(x, HEIGHT)
    return d * d / (HEIGHT / d * AREA)


def quad_solid_angle():
    """Ω of the axis-aligned quad from the origin: corner terms atan(x z / (h √(x² + z² + h²)))."""
    def corner(x, z):
        return math.atan(x * z / (HEIGHT * math.sqrt(x * x + z * z + HEIGHT * HEIGHT)))
    (x0, x1), (z0, z1) = LIGHT_X, LIGHT_Z
    return corner(x1, z1) - corner(x0, z1) - corner(x1, z0) + corner(x0, z0)


def uniform_points_panel(ax):
    xs = [LIGHT_X[0] + (i + 0.5) / SAMPLES * (LIGHT_X[1] - LIGHT_X[0]) for i in range(SAMPLES)]
    ax.plot(LIGHT_X, [HEIGHT, HEIGHT], color=LIGHT, lw=2)
    ax.plot([-0.7, 2.7], [0, 0], color=SURFACE, lw=2)
    ax.add_patch(Arc((0, 0), 1.0, 1.0, theta1=0, theta2=180, color=QUIET, ls="--"))
    ax.plot(0, 0, "o", color="black")
    label(ax, (0, -0.09), "p")
    for x in xs:
        ax.plot([0, x], [0, HEIGHT], color=QUIET, lw=0.6)
        ax.plot(x, HEIGHT, "o", color=LIGHT, ms=4)
        d = math.hypot(x, HEIGHT)
        ax.plot(0.5 * x / d, 0.5 * HEIGHT / d, "o", color=ACCENT, ms=4)
    label(ax, (1.0, HEIGHT + 0.12), "uniform points on the light: pdf_A = 1/A", color=LIGHT, fontsize=9)
    label(ax, (1.0, 0.3), "their directions from p\ncrowd where the light is\nfar and slanted",
          color=ACCENT, fontsize=9, ha="left")
    ax.set_xlim(-0.7, 2.7)
    ax.set_ylim(-0.2, 1.25)
    ax.set_title("the same points, seen from p")


def density_panel(ax):
    ax.set_aspect("auto")
    ax.axis("on")
    xs = [LIGHT_X[0] + i / 200 * (LIGHT_X[1] - LIGHT_X[0]) for i in range(201)]
    ax.plot(xs, [area_pdf_to_solid_angle(x) for x in xs], color=LIGHT, lw=2,
            label="area sampling: pdf_ω = d² / (cos θ_l A)")
    omega = quad_solid_angle()
    ax.axhline(1 / omega, color=RAY, lw=2, ls="--", label=f"solid-angle sampling: 1/Ω, Ω = {omega:.2f} sr")
    ax.set_ylim(0, None)
    ax.set_xlabel("x of the light point (p is below x = 0)")
    ax.set_ylabel("density per steradian")
    ax.legend(fontsize=8, frameon=False, loc="upper left")
    ax.set_title(f"along the quad's centre line (A = {AREA:g})")


def figures():
    fig, (solid, lobes) = new_figure(10.0, 4.0, panels=2)
    solid_angle_panel(solid)
    lobes_panel(lobes)
    pdf_fig, (points, density) = new_figure(10.0, 3.4, panels=2)
    uniform_points_panel(points)
    density_panel(density)
    return {"04_direct_lighting/images/diagram_radiometry.svg": fig,
            "04_direct_lighting/images/diagram_light_pdf.svg": pdf_fig}
