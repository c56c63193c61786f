// A medium that scatters: chapter 04's Medium (its transmittance) and what this chapter's path loop asks of
// it along every segment it traces through it:
//   sample_free_flight(t_max, c): where the path's next interaction is: a scattering event at t < t_max, or
//                                 none before the surface at t_max, drawn with the density of colour channel
//                                 c, with the weight that keeps the estimate unbiased;
//   phase():                      the phase function that scatters it there.
// A medium that only absorbs (chapter 07's glass) is not one: the loop attenuates its segments by T(t_max).
#pragma once

#include "04_direct_lighting/medium.hpp"
#include "phase_function.hpp"
#include "rt/core/math.hpp"

namespace rt {

// One free flight along a segment of length t_max (kInfinity when no surface is ahead), drawn with the
// density p_c of the path's colour channel c.
struct FreeFlight {
    bool scattered =
        false;  // true: a scattering event at distance t < t_max; false: the flight reached t_max
    Real t = 0;
    // The factor the path's throughput takes, per channel k: T_k(t) σ_s,k / p_c(t) at an event,
    // T_k(t_max) / P_c(no event) otherwise.
    Color weight{1};
    // p_k / p_c per channel k: how likely channel k's own sampling was to make the same flight. The path loop
    // multiplies these along the path and divides its throughput by their mean (spectral MIS).
    Color pdf_ratio{1};
};

// The colour channel u in [0, 1) picks, each with probability 1/3 (the channel of a path's free flights).
inline int pick_channel(Real u) {
    return u < Real(1) / 3 ? 0 : u < Real(2) / 3 ? 1 : 2;
}

class ScatteringMedium : public Medium {
  public:
    // The phase function of its scattering events.
    virtual const PhaseFunction& phase() const = 0;
    // `channel` (0, 1, 2: red, green, blue) is the one colour channel whose density draws the distance from
    // the uniform number u, chosen once per path (a medium of the same σ_t in every channel draws the same
    // either way).
    virtual FreeFlight sample_free_flight(Real t_max, int channel, Real u) const = 0;
};

}  // namespace rt
