// Rough glass: the GGX microfacet BSDF of Walter, Marschner, Li and Torrance 2007 ("Microfacet Models for
// Refraction through Rough Surfaces"), reflection and transmission. The surface is made of tiny smooth facets
// of normal m, each a smooth dielectric (dielectric.hpp); f sums what the facets that send wo to wi do.
// Directions point away from the surface, n is the normal on wo's side, η = η_t / η_i (the index on the far
// side over the index on wo's side), cos θ_x = n · x, and everything is computed in the frame where n = +z.
//   roughness r in (0, 1] (the scene's "roughness"):  α = r², clamped below at kMinAlpha.
//   GGX distribution:    D(m) = α² / (π ((m · n)² α² + |m × n|²)²)   (= α² / (π cos⁴θ_m (α² + tan²θ_m)²))
//   Smith masking:       G1(w) = 2 / (1 + √(1 + α² tan² θ_w)),   G(wo, wi) = G1(wo) G1(wi)
//                        (separable: Walter's form; the height-correlated 1 / (1 + Λ(wo) + Λ(wi)) is the
//                        reflection's, and would correlate a facet's two sides the wrong way for
//                        transmission, where a high point helps wo and hides wi)
//   half vectors:        reflection m = unit(wo + wi); transmission m = ±unit(wo + η wi), on n's side;
//                        a pair scatters only when wo · m > 0 and wi · m has the sign of wi · n
//   reflection:          f_r = F(wo · m) D(m) G / (4 |wo · n| |wi · n|)
//   transmission:        f_t = (1 − F(wo·m)) D(m) G |wo·m| |wi·m| / (|wo·n| |wi·n| (wo·m + η wi·m)²)
//                        for radiance; for importance (chapter 08) η² f_t: the BTDF is not symmetric, the
//                        generalized reciprocity f_t(wo, wi) / η_o² = f_t(wi, wo) / η_i² holds for radiance,
//                        and the importance BTDF is the radiance one with its arguments swapped
//   F:                   chapter 07's exact fresnel_dielectric(wo · m, η) (1 under total internal reflection)
// Sampling: m from the distribution of visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible
// Normals"), D_wo(m) = G1(wo) max(0, wo · m) D(m) / (wo · n); then reflection with probability F, else
// transmission (u_lobe, as the smooth dielectric chooses); then wi by the mirror or Snell's law about m:
//   pdf(wi) = D_wo(m) F / (4 |wo · m|)                                      (reflection)
//   pdf(wi) = D_wo(m) (1 − F) η² |wi · m| / (wo · m + η wi · m)²             (transmission)
// the half-vector density times the Jacobians dω_m / dω_i of Walter's eqs. 14 and 17 (η_i = 1, η_t = η).
// Why visible normals rather than Walter's D(m) |m · n|: no facet facing away from wo is drawn (Walter's
// sampler wastes those, more of them the more grazing wo is), and the sample weight f |cos θ_i| / pdf is
//   F G1(wi) / F = G1(wi) ≤ 1 (reflection),  G1(wi) / η² (transmitted radiance),  G1(wi) (importance),
// bounded at every angle, where Walter's weight |wo · m| G / (|wo · n| |m · n|) grows without bound at
// grazing wo. A sample whose wi leaves on the wrong side of the surface (a reflection below it, a refraction
// above it) is lost: pdf 0, f 0. That loss, and G < 1, is the energy single scattering loses: light that a
// real rough surface would scatter again off a neighbouring facet. eval, sample and pdf share one computation
// from (wo, wi), so they agree to the last bit.
#pragma once

#include "04_direct_lighting/bsdf.hpp"
#include "dielectric.hpp"
#include "rt/core/math.hpp"

namespace rt {

// α below this is taken as this: D's peak 1 / (π α²) stays near 3e7, far inside a float's range, where a
// roughness of 1e-6 (α = 1e-12) would overflow α⁴. A surface that smooth already looks smooth.
inline constexpr Real kMinAlpha = Real(1e-4);

// α = roughness², clamped to [kMinAlpha, 1].
Real ggx_alpha(Real roughness);
// D(m) for a unit m in the local frame (n = +z); 0 below the surface.
Real ggx_d(const Vec3& m, Real alpha);
// G1(w) / |cos θ_w| = 2 / (|w_z| + √(w_z² + α² (w_x² + w_y²))): finite at every angle (≤ 2 / α at the
// tangent plane), where G1 and 1 / |cos θ_w| alone are 0 and ∞.
Real smith_g1_over_cos(const Vec3& w, Real alpha);
// A visible normal for wo (local, wo_z >= 0) from u in [0, 1)²: density D_wo(m) above.
Vec3 sample_ggx_visible_normal(const Vec3& wo, Real alpha, Vec2 u);

class RoughDielectric final : public Bsdf {
  public:
    // η = η_t / η_i as for SmoothDielectric: ior seen from outside, 1 / ior from inside. η = 1 has no
    // rough BTDF (every facet passes light straight on: a delta), so this class loses those samples and
    // refraction_materials() builds the smooth dielectric there.
    RoughDielectric(Real roughness, Real eta, Transport transport);
    Color eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;
    BsdfSample sample(const Vec3& wo, const Vec3& n, Vec2 u, Real u_lobe) const override;
    Real pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;

    Real alpha;
    Real eta;
    Transport transport;

  private:
    struct Scattering {
        Real f = 0;
        Real pdf = 0;
    };
    // f and pdf for local wo and wi (n = +z): the one computation behind eval, sample and pdf.
    Scattering evaluate(const Vec3& wo, const Vec3& wi) const;
};

}  // namespace rt
