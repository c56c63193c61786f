#include "brdf.hpp"

#include <algorithm>
#include <cmath>

#include "frame.hpp"
#include "sampling.hpp"

namespace rt {
namespace {

bool above(const Vec3& wo, const Vec3& wi, const Vec3& n) {
    return glm::dot(wo, n) > 0 && glm::dot(wi, n) > 0;
}

// cos^e α for cos α = max(0, wi · axis); 0⁰ is taken as 1 only inside the lobe (cos α > 0).
Real lobe_power(const Vec3& wi, const Vec3& axis, Real exponent) {
    const Real c = std::min(Real(1), glm::dot(wi, axis));
    return c > 0 ? std::pow(c, exponent) : Real(0);
}

// Lambert: one constant, normalized so that albedo ρ reflects the fraction ρ, when wo and wi are both above
// the surface, else 0.
Color lambert_eval(const LambertBrdf& lambert, const Vec3& wo, const Vec3& wi, const Vec3& n) {
    // EXERCISE(ch04.lambert) § Four BRDFs
    return above(wo, wi, n) ? lambert.albedo * kInvPi : Color(0);
    // END EXERCISE
}

// The mirror's one direction wi = r(wo), pdf 1 (a delta), and the f for which the sample's weight
// f cos θ_i / pdf is the reflectance R; nothing (f = 0) when r(wo) is not above the surface.
BsdfSample mirror_sample(const MirrorBrdf& mirror, const Vec3& wo, const Vec3& n) {
    // EXERCISE(ch04.mirror) § Four BRDFs
    BsdfSample s;
    s.wi = reflect(wo, n);
    const Real cos_i = glm::dot(s.wi, n);
    s.f = cos_i > 0 ? mirror.reflectance / cos_i : Color(0);
    s.pdf = 1;
    s.delta = true;
    return s;
    // END EXERCISE
}

// The glossy BRDF's lobe f ∝ ρ cos^e α around `axis` (r(wo) for glossy), normalized so that about the normal
// it reflects the fraction ρ; 0 unless wo and wi are both above the surface.
Color lobe_eval(const Color& albedo, Real exponent, const Vec3& axis, const Vec3& wo, const Vec3& wi,
                const Vec3& n) {
    // EXERCISE(ch04.glossy) § Four BRDFs
    if (!above(wo, wi, n)) return Color(0);
    return albedo * ((exponent + 2) * Real(0.5) * kInvPi * lobe_power(wi, axis, exponent));
    // END EXERCISE
}

// Retro-reflective: the same normalized lobe, around wo itself.
Color retroreflective_eval(const RetroreflectiveBrdf& retro, const Vec3& wo, const Vec3& wi, const Vec3& n) {
    // EXERCISE(ch04.retroreflective) § Four BRDFs
    return lobe_eval(retro.albedo, retro.exponent, wo, wo, wi, n);
    // END EXERCISE
}

// The density of sample_power_cosine about `axis`.
Real lobe_pdf(Real exponent, const Vec3& axis, const Vec3& wi) {
    return power_cosine_pdf(glm::dot(wi, axis), exponent);
}

BsdfSample lobe_sample(const Color& albedo, Real exponent, const Vec3& axis, const Vec3& wo, const Vec3& n,
                       Vec2 u) {
    BsdfSample s;
    s.wi = glm::normalize(make_frame(axis).to_world(sample_power_cosine(u, exponent)));
    s.f = lobe_eval(albedo, exponent, axis, wo, s.wi, n);  // 0 when the lobe dips below the surface
    s.pdf = lobe_pdf(exponent, axis, s.wi);
    return s;
}

}  // namespace

LambertBrdf::LambertBrdf(const Color& albedo_)
    : Bsdf({.diffuse = true, .black = is_black(albedo_)}), albedo(albedo_) {}

Color LambertBrdf::eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const {
    return lambert_eval(*this, wo, wi, n);
}

BsdfSample LambertBrdf::sample(const Vec3& wo, const Vec3& n, Vec2 u, Real) const {
    BsdfSample s;
    s.wi = glm::normalize(make_frame(n).to_world(sample_cosine_hemisphere(u)));
    s.f = lambert_eval(*this, wo, s.wi, n);
    s.pdf = cosine_hemisphere_pdf(glm::dot(s.wi, n));
    return s;
}

Real LambertBrdf::pdf(const Vec3&, const Vec3& wi, const Vec3& n) const {
    return cosine_hemisphere_pdf(glm::dot(wi, n));
}

MirrorBrdf::MirrorBrdf(const Color& reflectance_)
    : Bsdf({.delta = true, .black = is_black(reflectance_)}), reflectance(reflectance_) {}

BsdfSample MirrorBrdf::sample(const Vec3& wo, const Vec3& n, Vec2, Real) const {
    return mirror_sample(*this, wo, n);
}

GlossyBrdf::GlossyBrdf(const Color& albedo_, Real exponent_)
    : Bsdf({.black = is_black(albedo_)}), albedo(albedo_), exponent(exponent_) {}

Color GlossyBrdf::eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const {
    return lobe_eval(albedo, exponent, reflect(wo, n), wo, wi, n);
}

BsdfSample GlossyBrdf::sample(const Vec3& wo, const Vec3& n, Vec2 u, Real) const {
    return lobe_sample(albedo, exponent, reflect(wo, n), wo, n, u);
}

Real GlossyBrdf::pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const {
    return lobe_pdf(exponent, reflect(wo, n), wi);
}

RetroreflectiveBrdf::RetroreflectiveBrdf(const Color& albedo_, Real exponent_)
    : Bsdf({.black = is_black(albedo_)}), albedo(albedo_), exponent(exponent_) {}

Color RetroreflectiveBrdf::eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const {
    return retroreflective_eval(*this, wo, wi, n);
}

BsdfSample RetroreflectiveBrdf::sample(const Vec3& wo, const Vec3& n, Vec2 u, Real) const {
    return lobe_sample(albedo, exponent, wo, wo, n, u);
}

Real RetroreflectiveBrdf::pdf(const Vec3& wo, const Vec3& wi, const Vec3&) const {
    return lobe_pdf(exponent, wo, wi);
}

Real phong_exponent(Real roughness) {
    const Real r = std::max(roughness, Real(1e-3));
    return std::max(Real(0), 2 / (r * r) - 2);
}

}  // namespace rt
