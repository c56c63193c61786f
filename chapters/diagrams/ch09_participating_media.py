"""Chapter 09: free flight and the phase function. The distance to the next collision in a medium of
extinction σ has the density σ e^(−σ t) and is sampled by t = −ln(1 − u)/σ; the Henyey–Greenstein phase
function p(θ) = (1 − g²) / (4π (1 + g² − 2 g cos θ)^(3/2)) for several g (henyey_greenstein.cpp)."""

import math

from figure_style import ACCENT, LIGHT, QUIET, RAY, label, new_figure

SIGMA = 1.5


def henyey_greenstein(cos_theta, g):
    denominator = 1 + g * g - 2 * g * cos_theta
    return (1 - g * g) / (4 * math.pi * denominator ** 1.5)


def figures():
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
    return {"09_participating_media/images/diagram_free_flight_phase.svg": fig}
