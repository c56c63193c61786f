// A phase function p(wo, wi): the density (per steradian) of the direction wi a scattering event sends light
// into, both directions pointing away from the event (the path arrived along −wo). ∫ p dω_i = 1. It is to a
// point in a medium what the BSDF is to a surface: evaluated, sampled, and its density asked for MIS.
#pragma once

#include "rt/core/math.hpp"

namespace rt {

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

}  // namespace rt
