#include "rough_dielectric.hpp"

#include <algorithm>
#include <cmath>

#include "04_direct_lighting/frame.hpp"
#include "fresnel.hpp"
#include "snell.hpp"

namespace rt {
namespace {

// |wo + η wi|² below this: the generalized half vector has no direction (η = 1 and wi = −wo).
constexpr Real kMinHalfLength2 = Real(1e-12);

}  // namespace

Real ggx_alpha(Real roughness) {
    return std::clamp(roughness * roughness, kMinAlpha, Real(1));
}

Real ggx_d(const Vec3& m, Real alpha) {
    if (!(m.z > 0)) return 0;
    const Real a2 = alpha * alpha;
    const Real s = m.z * m.z * a2 + (m.x * m.x + m.y * m.y);  // cos⁴θ (α² + tan²θ)
    return a2 / (kPi * s * s);
}

Real smith_g1_over_cos(const Vec3& w, Real alpha) {
    const Real c = std::abs(w.z);
    return 2 / (c + std::sqrt(c * c + alpha * alpha * (w.x * w.x + w.y * w.y)));
}

Vec3 sample_ggx_visible_normal(const Vec3& wo, Real alpha, Vec2 u) {
    // Heitz 2018: stretch wo to the configuration where α = 1, sample the projected hemisphere's disc (the
    // half facing away from wo squeezed toward it), lift the point to the hemisphere, unstretch.
    const Vec3 vh = glm::normalize(Vec3(alpha * wo.x, alpha * wo.y, std::max(wo.z, Real(0))));
    const Real lensq = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = lensq > 0 ? Vec3(-vh.y, vh.x, 0) / std::sqrt(lensq) : Vec3(1, 0, 0);
    const Vec3 t2 = glm::cross(vh, t1);
    const Real r = std::sqrt(u.x);
    const Real phi = 2 * kPi * u.y;
    const Real p1 = r * std::cos(phi);
    const Real s = (1 + vh.z) / 2;
    const Real p2 = (1 - s) * std::sqrt(std::max(Real(0), 1 - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(Real(0), 1 - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(Vec3(alpha * nh.x, alpha * nh.y, std::max(nh.z, Real(0))));
}

RoughDielectric::RoughDielectric(Real roughness, Real eta_, Transport transport_)
    : Bsdf({.transmission = true}), alpha(ggx_alpha(roughness)), eta(eta_), transport(transport_) {}

RoughDielectric::Scattering RoughDielectric::evaluate(const Vec3& wo, const Vec3& wi) const {
    const Real cos_o = wo.z, cos_i = wi.z;
    if (!(cos_o > 0) || cos_i == 0) return {};
    const bool reflection = cos_i > 0;
    const Vec3 h = reflection ? wo + wi : wo + eta * wi;
    const Real length2 = glm::dot(h, h);
    if (!(length2 > kMinHalfLength2)) return {};
    Vec3 m = h / std::sqrt(length2);
    if (m.z < 0) m = -m;
    const Real om = glm::dot(wo, m), im = glm::dot(wi, m);
    // Only a facet that faces wo, and that wi sees from the side it leaves on, scatters the pair.
    if (!(om > 0) || !(reflection ? im > 0 : im < 0)) return {};
    const Real D = ggx_d(m, alpha);
    const Real g_o = smith_g1_over_cos(wo, alpha);  // G1(wo) / cos θ_o
    const Real g_i = smith_g1_over_cos(wi, alpha);  // G1(wi) / |cos θ_i|
    const Real F = fresnel_dielectric(om, eta);
    const Real visible = g_o * om * D;  // D_wo(m) = G1(wo) (wo · m) D(m) / cos θ_o
    if (reflection) {
        // f_r = F D G1(wo) G1(wi) / (4 cos θ_o cos θ_i);  pdf = D_wo(m) F / (4 wo · m).
        return {F * D * g_o * g_i / 4, visible * F / (4 * om)};
    }
    const Real denominator = (om + eta * im) * (om + eta * im);  // (wo · m + η wi · m)² = |wo + η wi|²
    if (!(denominator > kMinHalfLength2)) return {};
    // f_t = (1 − F) D G1(wo) G1(wi) |wo · m| |wi · m| / (cos θ_o |cos θ_i| (wo · m + η wi · m)²) for
    // radiance, η² times that for importance;  pdf = D_wo(m) (1 − F) η² |wi · m| / (wo · m + η wi · m)².
    const Real T = 1 - F;
    const Real f_radiance = T * D * g_o * g_i * om * -im / denominator;
    const Real eta2 = eta * eta;
    return {transport == Transport::kImportance ? eta2 * f_radiance : f_radiance,
            visible * T * eta2 * -im / denominator};
}

Color RoughDielectric::eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const {
    const Frame frame = make_frame(n);
    return Color(evaluate(frame.to_local(wo), frame.to_local(wi)).f);
}

Real RoughDielectric::pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const {
    const Frame frame = make_frame(n);
    return evaluate(frame.to_local(wo), frame.to_local(wi)).pdf;
}

BsdfSample RoughDielectric::sample(const Vec3& wo_world, const Vec3& n, Vec2 u, Real u_lobe) const {
    const Frame frame = make_frame(n);
    const Vec3 wo = frame.to_local(wo_world);
    BsdfSample s;  // pdf 0: lost
    if (!(wo.z > 0)) return s;
    const Vec3 m = sample_ggx_visible_normal(wo, alpha, u);
    const Real om = glm::dot(wo, m);
    if (!(om > 0)) return s;
    // The lobe, as the smooth dielectric chooses it about n, here about m: reflection with probability F.
    // fresnel_dielectric is below 1 exactly when refract finds a direction (the same kTirCos2 test).
    Vec3 wi = 2 * om * m - wo;
    bool transmitted = false;
    if (u_lobe >= fresnel_dielectric(om, eta)) {
        if (const auto wt = refract(wo, m, eta)) {
            wi = *wt;
            transmitted = true;
        }
    }
    // Evaluated from the world direction it returns, as eval and pdf will see it: the same bits.
    const Vec3 world = glm::normalize(frame.to_world(wi));
    wi = frame.to_local(world);
    // A reflection below the surface or a refraction above it leaves the surface on the wrong side: lost.
    if (transmitted ? !(wi.z < 0) : !(wi.z > 0)) return s;
    const Scattering e = evaluate(wo, wi);
    if (!(e.pdf > 0)) return s;
    s.wi = world;
    s.f = Color(e.f);
    s.pdf = e.pdf;
    s.transmitted = transmitted;
    if (transmitted && transport == Transport::kRadiance) s.roulette_scale = 1 / (eta * eta);
    return s;
}

}  // namespace rt
