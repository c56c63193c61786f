// How a path finds the light scattered toward it along a segment through a medium (Kulla and Fajardo 2012;
// Cycles' volume sampling "distance", "equiangular", "multiple importance"):
//   free-flight: the next-event estimate at the scattering event free flight draws, p_ff(t) = σ_t e^(−σ_t t):
//                many events in thin fog land where the lamp gives little;
//   equiangular: one more point per segment, t drawn toward a point on a light (equiangular.hpp), with its
//                own next-event estimate; the free-flight event's estimate is dropped wherever that point
//                could have been drawn (weights 0 and 1: still one sampler per t);
//   mis:         both, each weighted by the power heuristic of p_ff and p_eq (two-sample MIS).
// Both estimate ∫ T(t) σ_s L_light(x(t)) dt over [0, t_max), w_ff(t) + w_eq(t) = 1 at every t, so nothing is
// counted twice; light the path's phase-sampled direction meets is weighed against the light sampler as
// before. Served: segments of grey media (σ_t the same in every channel: one free-flight density, not the
// chromatic media's spectral MIS, whose density is the whole path's) that end at a surface (t_max finite);
// other segments keep free flight.
#pragma once

#include "06_monte_carlo/mis.hpp"
#include "homogeneous_medium.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/core/math.hpp"
#include "rt/core/ray.hpp"

namespace rt {

enum class DistanceSampling { kFreeFlight, kEquiangular, kMis };

constexpr auto names_of(DistanceSampling) {
    return enum_names<DistanceSampling>("--distance-sampling",
                                        {{DistanceSampling::kFreeFlight, "free-flight"},
                                         {DistanceSampling::kEquiangular, "equiangular"},
                                         {DistanceSampling::kMis, "mis"}});
}

// A segment served by equiangular sampling: its ray, its end, the grey medium that fills it, and the distance
// t_event of the free-flight scattering event in it (when there is one).
struct LitSegment {
    Ray ray;
    Real t_max = 0;
    const HomogeneousMedium* medium = nullptr;
    Real t_event = 0;

    Real sigma_t() const { return medium->sigma_t.r; }
};

// The free-flight density of an event at t: p_ff(t) = σ_t e^(−σ_t t).
inline Real free_flight_pdf(Real sigma_t, Real t) {
    return sigma_t * std::exp(-sigma_t * t);
}

// w_ff(t) for the free-flight event's estimate, given both densities there.
inline Real free_flight_weight(DistanceSampling s, Real p_ff, Real p_eq) {
    if (s == DistanceSampling::kMis) return power_heuristic(p_ff, p_eq);
    return s == DistanceSampling::kEquiangular && p_eq > 0 ? Real(0) : Real(1);
}

// w_eq(t) for the equiangular point's estimate (p_eq > 0 there): 1 − w_ff.
inline Real equiangular_weight(DistanceSampling s, Real p_ff, Real p_eq) {
    return s == DistanceSampling::kMis ? power_heuristic(p_eq, p_ff) : Real(1);
}

}  // namespace rt
