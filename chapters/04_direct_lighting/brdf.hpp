// The four BRDFs of the course, each a Bsdf (bsdf.hpp) that only reflects. A BRDF f(wo, wi) is the ratio of
// the radiance reflected toward wo to the irradiance arriving from wi: dL_o(wo) = f(wo, wi) L_i(wi) cos θ_i
// dω_i. Directions point away from the surface; n is the unit normal on wo's side. Each BRDF has
//   eval(wo, wi, n):   f(wo, wi), 0 unless both directions are above the surface;
//   sample(wo, n, u):  a direction wi drawn with density pdf (solid angle), with f(wo, wi) — for chapter 06;
//   pdf(wo, wi, n):    the density of sample() at wi.
// Energy conservation: ∫ f(wo, wi) cos θ_i dω_i <= 1 for every wo. Reciprocity: f(wo, wi) = f(wi, wo).
#pragma once

#include "bsdf.hpp"
#include "rt/core/math.hpp"

namespace rt {

// Ideal diffuse (Lambert): f = ρ times the constant for which ∫ f cos = ρ, the same for every pair of
// directions above the surface.
// Sampled cosine-weighted: pdf = cos θ_i / π.
class LambertBrdf final : public Bsdf {
  public:
    explicit LambertBrdf(const Color& albedo);
    Color eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;
    BsdfSample sample(const Vec3& wo, const Vec3& n, Vec2 u, Real u_lobe) const override;
    Real pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;

    Color albedo;
};

// Ideal specular: all light from wi leaves along its mirror image r(wi) = 2 (n · wi) n − wi. f is a delta
// (Dirac) distribution: eval is 0 for every wi a light sample can produce (the set r(wo) has measure zero),
// so the direct term of a mirror from area and point lights is 0. sample() returns wi = r(wo) with pdf = 1
// and the f for which f cos θ_i / pdf = R, the reflectance.
class MirrorBrdf final : public Bsdf {
  public:
    explicit MirrorBrdf(const Color& reflectance);
    Color eval(const Vec3&, const Vec3&, const Vec3&) const override { return Color(0); }
    BsdfSample sample(const Vec3& wo, const Vec3& n, Vec2 u, Real u_lobe) const override;
    Real pdf(const Vec3&, const Vec3&, const Vec3&) const override { return 0; }

    Color reflectance;
};

// Glossy: the normalized modified Phong lobe around the mirror direction r(wo) (Lafortune & Willems 1994):
// f = ρ c cos^e α, with cos α = max(0, wi · r(wo)) and c the constant that makes ∫ f cos = ρ at normal
// incidence (less elsewhere). wi · r(wo) = wo · r(wi), so it is reciprocal. e = phong_exponent(roughness).
// Sampled from the lobe: pdf = power_cosine_pdf(cos α, e).
class GlossyBrdf final : public Bsdf {
  public:
    GlossyBrdf(const Color& albedo, Real exponent);
    Color eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;
    BsdfSample sample(const Vec3& wo, const Vec3& n, Vec2 u, Real u_lobe) const override;
    Real pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;

    Color albedo;
    Real exponent;
};

// Retro-reflective: the same normalized lobe around wo itself (light returns toward where it came from):
// f = ρ c cos^e β, cos β = max(0, wi · wo), c the glossy lobe's constant; symmetric in wi and wo.
// pdf = power_cosine_pdf(cos β, e).
class RetroreflectiveBrdf final : public Bsdf {
  public:
    RetroreflectiveBrdf(const Color& albedo, Real exponent);
    Color eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;
    BsdfSample sample(const Vec3& wo, const Vec3& n, Vec2 u, Real u_lobe) const override;
    Real pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;

    Color albedo;
    Real exponent;
};

// The Phong exponent of a roughness r in (0, 1]: e = 2 / r² − 2 (the relation Walter et al. 2007 give between
// Phong and Beckmann microfacet distributions); r = 1 gives e = 0, a diffuse-like lobe. r is clamped to >=
// 1e-3.
Real phong_exponent(Real roughness);

// The mirror image of w about n: r = 2 (n · w) n − w.
inline Vec3 reflect(const Vec3& w, const Vec3& n) {
    return 2 * glm::dot(n, w) * n - w;
}

}  // namespace rt
