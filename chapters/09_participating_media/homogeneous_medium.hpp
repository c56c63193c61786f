// A homogeneous participating medium: per unit of length it absorbs at the rate σ_a and scatters at the rate
// σ_s, so it removes light from a ray at the extinction rate σ_t = σ_a + σ_s (the radiative transfer equation
// of the lesson). Per colour channel:
//   transmittance     T(d) = exp(−σ_t d)             (what is left of a ray after a distance d)
//   single-scattering albedo  ω = σ_s / σ_t          (the fraction of each interaction that scatters)
//   mean free path    1 / σ_t                        (the mean distance between interactions)
// Free flight draws the distance to the next interaction with density p(t) = σ_t e^(−σ_t t), by inversion of
// its cumulative distribution. Before the surface at t_max the path scatters there (weight T(t) σ_s / p(t) = ω);
// past it, it reaches the surface (weight T(t_max) / P(t ≥ t_max) = 1).
//
// Chromatic media (σ_t differing per channel) have one such density per channel. Single-sample spectral MIS
// (pbrt-v4's): choose a channel c uniformly, draw t from p_c, and weight every channel by the average density
// p̄(t) = (1/3) Σ_k p_k(t) — the balance heuristic over the three channels' samplers: weight / mean(pdf_ratio)
// below, at most 3 ω. The path loop applies it to the whole path (the product of the densities along it), so
// a long walk's weight stays bounded too. The naive choice (weight by the chosen channel's own p_c, `weight`
// alone) is unbiased too, but where one channel is much denser than another its weight grows without bound,
// e^((σ_c − σ_k) t), and its variance is infinite.
#pragma once

#include "henyey_greenstein.hpp"
#include "rt/core/math.hpp"
#include "rt/core/scene.hpp"
#include "scattering_medium.hpp"

namespace rt {

// One free flight over [0, t_max) of a medium of extinction σ_t and scattering σ_s, its distance drawn with
// channel c's density from u.
FreeFlight sample_free_flight(const Color& sigma_t, const Color& sigma_s, Real t_max, int channel, Real u);

class HomogeneousMedium final : public ScatteringMedium {
  public:
    explicit HomogeneousMedium(const MediumDesc& desc);
    Color transmittance(Real distance) const override;
    const PhaseFunction& phase() const override { return phase_; }
    FreeFlight sample_free_flight(Real t_max, int channel, Real u) const override;

    Color sigma_a, sigma_s, sigma_t;

  private:
    HenyeyGreenstein phase_;
};

}  // namespace rt
