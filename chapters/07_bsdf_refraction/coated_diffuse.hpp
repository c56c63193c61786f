// Coated diffuse ("plastic"): a smooth clear coat of index η over a Lambert base of reflectance ρ, with
// nothing between them (Weidlich & Wilkie 2007, Kelemen & Szirmay-Kalos 2001; Mitsuba's smoothplastic).
// The coat reflects F(θ_o) as a mirror; the rest, T = 1 − F, enters, meets the base, and leaves as a
// diffuse lobe after bouncing between base and coat any number of times. Inside, the base's light is
// diffuse, so the coat reflects back, on average, the internal reflectance F̄_int (total internal reflection
// included); each round trip keeps ρ F̄_int, and the geometric series sums to 1 / (1 − ρ F̄_int):
//   coat:   a delta lobe along r(wo),                     f |cos θ_i| / pdf = F(cos θ_o)
//   base:   f(wo, wi) = ρ T(cos θ_i) T(cos θ_o) / (π η² (1 − ρ F̄_int))
// symmetric in wo and wi (reciprocal); 1 / η² is the radiance that entering and leaving a denser layer
// spreads out. F̄_int = 1 − (1 − F̄_ext) / η², with F̄_ext = ∫ F(cos θ, η) 2 cos θ sin θ dθ, the
// hemispherical average of the exact Fresnel reflectance from outside, in closed form (below). With ρ = 1
// the albedo is exactly 1 at every angle: F + T (1 − F̄_int) / (1 − F̄_int).
// Sampling: the coat with probability F / (F + T a), a = ρ̄ (1 − F̄_int) / (1 − ρ̄ F̄_int) the share of what
// enters that leaves again (ρ̄ the channels' mean), the base by the cosine otherwise; each lobe is chosen in
// proportion to the energy it returns. Its delta samples are marked (BsdfSample::delta): the path loops
// follow them like a mirror, and take light samples for the base.
#pragma once

#include "04_direct_lighting/bsdf.hpp"
#include "rt/core/math.hpp"

namespace rt {

// F̄_ext for η >= 1: the average reflectance of a smooth dielectric under uniform (diffuse) light from
// outside, in closed form: the integral done exactly (a test holds it to quadrature; d'Eon & Irving 2011 fit
// it by a polynomial instead). 0 at η = 1.
Real average_fresnel_outside(Real eta);
// F̄_int = 1 − (1 − F̄_ext) / η²: the same from inside, where everything beyond the critical angle reflects.
Real average_fresnel_inside(Real eta);

class CoatedDiffuse final : public Bsdf {
  public:
    // ρ in [0, 1] per channel (the base's reflectance), η >= 1 the coat's index.
    CoatedDiffuse(const Color& reflectance, Real eta);
    Color eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;
    BsdfSample sample(const Vec3& wo, const Vec3& n, Vec2 u, Real u_lobe) const override;
    Real pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;

    Real eta;
    Color base;           // ρ / (π η² (1 − ρ F̄_int)): the base's f without its two T factors
    Real base_share = 0;  // a: the share of what enters that leaves again

  private:
    // The probability of the coat's lobe for wo: F / (F + T a); 1 when nothing leaves the base.
    Real coat_probability(Real cos_o) const;
};

}  // namespace rt
