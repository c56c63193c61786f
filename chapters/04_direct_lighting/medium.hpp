// What fills a shape (or the space between the shapes): a participating medium, the volume counterpart of
// the Bsdf. The material table hands one out for each dielectric that is not clear, and the path loop
// (chapter 06) asks it three things along every segment it traces through it:
//   transmittance(d):            T(d), the fraction of radiance left after a distance d (chapter 07's
//                                Beer–Lambert glass answers only this);
//   sample_free_flight(t_max, c): where the path's next interaction is: a scattering event at t < t_max, or
//                                none before the surface at t_max, drawn with the density of colour channel
//                                c, with the weight that keeps the estimate unbiased;
//   phase():                     the phase function that scatters it there (null: it only absorbs).
// Chapter 09 implements them for scattering media. As with Bsdf, an interface (not a variant) lets the later
// chapter add its media without this chapter naming them.
#pragma once

#include "rt/core/math.hpp"

namespace rt {

// A phase function p(wo, wi): the density (per steradian) of the direction wi a scattering event sends light
// into, both directions pointing away from the event (the path arrived along −wo). ∫ p dω_i = 1.
struct PhaseSample {
    Vec3 wi{0, 0, 1};  // unit
    Real p = 0;        // p(wo, wi)
    Real pdf = 0;      // the density sample() drew wi with (p itself when sampled exactly)
};

class PhaseFunction {
  public:
    virtual ~PhaseFunction() = default;
    virtual Real eval(const Vec3& wo, const Vec3& wi) const = 0;
    virtual PhaseSample sample(const Vec3& wo, Vec2 u) const = 0;
    virtual Real pdf(const Vec3& wo, const Vec3& wi) const = 0;
};

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
    // multiplies these along the path and divides its throughput by their mean (spectral MIS, chapter 09).
    Color pdf_ratio{1};
};

// The colour channel u in [0, 1) picks, each with probability 1/3 (the channel of a path's free flights).
inline int pick_channel(Real u) {
    return u < Real(1) / 3 ? 0 : u < Real(2) / 3 ? 1 : 2;
}

class Medium {
  public:
    virtual ~Medium() = default;
    // The fraction of radiance left after `distance` inside it, per colour channel.
    virtual Color transmittance(Real distance) const = 0;
    // The phase function of its scattering events; null for a medium that only absorbs.
    virtual const PhaseFunction* phase() const { return nullptr; }
    // `channel` (0, 1, 2: red, green, blue) is the one colour channel whose density draws the distance from
    // the uniform number u, chosen once per path (a medium of the same σ_t in every channel draws the same
    // either way). A medium that only absorbs: the flight always reaches t_max, weighted by T(t_max); the
    // path loop draws no u for it (so chapter 07's images do not depend on this hook).
    virtual FreeFlight sample_free_flight(Real t_max, int /*channel*/, Real /*u*/) const {
        return {false, t_max, transmittance(t_max), Color(1)};
    }
};

}  // namespace rt
