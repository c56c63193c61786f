"""Chapter 09: free flight and the phase function. The distance to the next collision in a medium of
extinction σ has the density σ e^(−σ t) and is sampled by t = −ln(1 − u)/σ; the Henyey–Greenstein phase
function p(θ) = (1 − g²) / (4π (1 + g² − 2 g cos θ)^(3/2)) for several g (henyey_greenstein.cpp).
And equiangular sampling toward a point x_l of a lamp, its foot Δ on the ray and its distance D from it:
θ uniform between θ(0) and θ(t_max), t = Δ + D tan θ, pdf(t) = D / ((θ(t_max) − θ(0)) (D² + (t − Δ)²)),
against free flight's σ e^(−σ t) and the shape of what the lamp gives, T(t) / |x(t) − x_l|² (equiangular.*)."""

import math

from figure_style import ACCENT, LIGHT, QUIET, RAY, SURFACE, label, new_figure

SIGMA = 1.5
# The equiangular figure: thin fog along a segment that ends on a surface, a lamp near its far half.
THIN_SIGMA = 0.2
SEGMENT = 6.0   # t_max
FOOT = 3.5      # Δ
OFFSET = 1.0    # D
POINTS = 12


def henyey_greenstein(cos_theta, g):
    denominator = 1 + g * g - 2 * g * cos_theta
    return (1 - g * g) / (4 * math.pi * denominator ** 1.5)


def free_flight_phase_figure():
    fig = new_figure(10.0, 3.8, panels=2)[0]
    flight, phase = fig.axes
    flight.set_aspect("auto")
    flight.axis("on")
    ts = [i * 0.02 for i in range(251)]
    flight.plot(ts, [SIGMA * math.exp(-SIGMA * t) for t in ts], color=ACCENT, lw=2, label="pdf σ e^(−σt)")
    flight.plot(ts, [math.exp(-SIGMA * t) for t in ts], color=RAY, lw=1.2, ls="--",
                label="transmittance T(t) = e^(−σt)")
    samples = [-math.log(1 - (i + 0.5) / 16) / SIGMA for i in range(16)]
    flight.plot(samples, [0.02] * len(samples), "|", color="black", ms=14, label="t = −ln(1 − u)/σ, 16 u's")
    flight.set_xlabel("distance t (σ = 1.5: mean free path 1/σ = 0.67)")
    flight.legend(fontsize=8, frameon=False)
    flight.set_title("free flight: where the next collision is")

    thetas = [math.radians(i) for i in range(361)]
    for g, colour in ((0.0, QUIET), (0.3, LIGHT), (0.6, ACCENT), (-0.3, RAY)):
        radius = [henyey_greenstein(math.cos(t), g) for t in thetas]
        phase.plot([r * math.cos(t) for r, t in zip(radius, thetas)],
                   [r * math.sin(t) for r, t in zip(radius, thetas)], color=colour, lw=1.6, label=f"g = {g}")
    phase.annotate("", xy=(0.25, 0), xytext=(-0.6, 0), arrowprops=dict(arrowstyle="-|>", color="black"))
    label(phase, (-0.6, 0.05), "travel", fontsize=8, ha="left", va="bottom")
    phase.legend(fontsize=8, frameon=False, loc="upper left")
    label(phase, (0.15, -0.5), "p(θ) = (1 − g²) / (4π (1 + g² − 2g cos θ)^(3/2))", fontsize=8)
    phase.set_xlim(-0.65, 1.0)
    phase.set_ylim(-0.55, 0.45)
    phase.set_title("Henyey–Greenstein: g is the mean cosine")
    return fig


def equiangular_angle(t):
    """θ(t) = atan((t − Δ) / D): the angle under which x_l sees x(t)."""
    return math.atan((t - FOOT) / OFFSET)


def equiangular_pdf(t):
    span = equiangular_angle(SEGMENT) - equiangular_angle(0)
    return OFFSET / (span * (OFFSET ** 2 + (t - FOOT) ** 2))


def equiangular_figure():
    fig, (side, densities) = new_figure(11.0, 3.8, panels=2)
    wide_left = fig.add_gridspec(1, 2, width_ratios=[1.7, 1])  # the side view is wide and flat: more room
    side.set_subplotspec(wide_left[0])
    densities.set_subplotspec(wide_left[1])
    # The segment seen from the side, the lamp above it: equiangular points at equal angles from x_l.
    us = [(i + 0.5) / POINTS for i in range(POINTS)]
    theta0, theta1 = equiangular_angle(0), equiangular_angle(SEGMENT)
    equiangular = [FOOT + OFFSET * math.tan(theta0 + u * (theta1 - theta0)) for u in us]
    free_flight = [-math.log(1 - u) / THIN_SIGMA for u in us]
    side.plot([0, SEGMENT], [0, 0], color=SURFACE, lw=1.5)
    side.plot([SEGMENT, SEGMENT], [-0.5, 0.5], color=SURFACE, lw=3)
    label(side, (SEGMENT, 0.62), "surface", fontsize=8)
    label(side, (0, 0.2), "x(0)", fontsize=8)
    for t in equiangular:
        side.plot([FOOT, t], [OFFSET, 0], color=LIGHT, lw=0.7)
        side.plot(t, 0, "|", color=LIGHT, ms=10, mew=1.5)
    inside = [t for t in free_flight if t < SEGMENT]
    side.plot(inside, [-0.3] * len(inside), "|", color=RAY, ms=10, mew=1.5, ls="none")
    label(side, (-0.2, 0), "equiangular", color=LIGHT, fontsize=8, ha="right")
    label(side, (-0.2, -0.3), "free flight", color=RAY, fontsize=8, ha="right")
    label(side, (SEGMENT + 0.15, -0.3), f"{len(free_flight) - len(inside)} pass t_max", color=RAY, fontsize=8,
          ha="left")
    side.plot(FOOT, OFFSET, "*", color=LIGHT, ms=14)
    label(side, (FOOT, OFFSET + 0.25), "lamp x_l", color=LIGHT, fontsize=9)
    side.plot([FOOT, SEGMENT + 0.5], [OFFSET, OFFSET], color=QUIET, lw=0.8, ls=":")
    side.annotate("", xy=(SEGMENT + 0.5, OFFSET), xytext=(SEGMENT + 0.5, 0),
                  arrowprops=dict(arrowstyle="<->", color=QUIET))
    label(side, (SEGMENT + 0.62, OFFSET / 2), "D", color=QUIET, fontsize=9, ha="left")
    side.annotate("", xy=(FOOT, -0.65), xytext=(0, -0.65), arrowprops=dict(arrowstyle="<->", color=QUIET))
    label(side, (FOOT / 2, -0.8), "Δ", color=QUIET, fontsize=9)
    side.plot([FOOT, FOOT], [-0.7, 0], color=QUIET, lw=0.8, ls=":")
    label(side, (SEGMENT / 2, -1.15), f"the same {POINTS} u's; Δ = {FOOT:g}, D = {OFFSET:g}, "
                                      f"t_max = {SEGMENT:g}, free flight's σ = {THIN_SIGMA}", fontsize=8)
    side.set_xlim(-1.7, SEGMENT + 1.3)
    side.set_ylim(-1.3, OFFSET + 0.45)
    side.set_title("equal angles from the lamp")

    densities.set_aspect("auto")
    densities.axis("on")
    ts = [SEGMENT * i / 400 for i in range(401)]
    lamp = [math.exp(-THIN_SIGMA * t) / (OFFSET ** 2 + (t - FOOT) ** 2) for t in ts]
    area = sum((a + b) / 2 for a, b in zip(lamp, lamp[1:])) * SEGMENT / 400
    densities.plot(ts, [v / area for v in lamp], color=QUIET, lw=4, alpha=0.6,
                   label="the lamp's light: ∝ T(t) / |x(t) − x_l|²")
    densities.plot(ts, [equiangular_pdf(t) for t in ts], color=LIGHT, lw=1.8,
                   label="equiangular: ∝ D / (D² + (t − Δ)²)")
    densities.plot(ts, [THIN_SIGMA * math.exp(-THIN_SIGMA * t) for t in ts], color=RAY, lw=1.8, ls="--",
                   label=f"free flight: σ e^(−σt)")
    densities.set_xlim(0, SEGMENT)
    densities.set_ylim(0, 1.5 * equiangular_pdf(FOOT))
    densities.set_xlabel("distance t along the ray")
    densities.set_ylabel("density per unit t")
    densities.legend(fontsize=8, frameon=False, loc="upper left")
    densities.set_title("the densities along the ray")
    return fig


def figures():
    return {"09_participating_media/images/diagram_free_flight_phase.svg": free_flight_phase_figure(),
            "09_participating_media/images/diagram_equiangular.svg": equiangular_figure()}
