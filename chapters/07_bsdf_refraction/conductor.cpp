#include "conductor.hpp"

#include "04_direct_lighting/brdf.hpp"
#include "04_direct_lighting/frame.hpp"
#include "fresnel.hpp"
#include "rough_dielectric.hpp"

namespace rt {

Conductor::Conductor(const Color& eta_, const Color& k_, Real roughness)
    : Bsdf({.delta = roughness == 0}), eta(eta_), k(k_), alpha(roughness == 0 ? 0 : ggx_alpha(roughness)) {}

Conductor::Scattering Conductor::evaluate(const Vec3& wo, const Vec3& wi) const {
    const Real cos_o = wo.z, cos_i = wi.z;
    if (!(cos_o > 0) || !(cos_i > 0)) return {};
    const Vec3 m = glm::normalize(wo + wi);
    const Real om = glm::dot(wo, m);
    if (!(om > 0)) return {};
    const Real D = ggx_d(m, alpha);
    const Real g1_o = smith_g1_over_cos(wo, alpha) * cos_o;  // G1(wo)
    const Real g1_i = smith_g1_over_cos(wi, alpha) * cos_i;  // G1(wi)
    const Real G2 = 1 / (1 / g1_o + 1 / g1_i - 1);           // 1 / (1 + Λ(wo) + Λ(wi))
    // f = F D G2 / (4 cos θ_o cos θ_i);  pdf = G1(wo) D / (4 cos θ_o).
    return {D * G2 / (4 * cos_o * cos_i), g1_o * D / (4 * cos_o), om};
}

Color Conductor::f_of(const Scattering& e) const {
    return e.pdf > 0 ? fresnel_conductor(e.cos_m, eta, k) * e.f_over_fresnel : Color(0);
}

Color Conductor::eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const {
    if (flags().delta) return Color(0);
    const Frame frame = make_frame(n);
    return f_of(evaluate(frame.to_local(wo), frame.to_local(wi)));
}

Real Conductor::pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const {
    if (flags().delta) return 0;
    const Frame frame = make_frame(n);
    return evaluate(frame.to_local(wo), frame.to_local(wi)).pdf;
}

BsdfSample Conductor::sample(const Vec3& wo_world, const Vec3& n, Vec2 u, Real) const {
    BsdfSample s;  // pdf 0: lost
    if (flags().delta) {
        // The mirror of chapter 04 with the Fresnel colour of the angle: f = F(cos θ) / cos θ.
        const Real cos_o = glm::dot(wo_world, n);
        if (!(cos_o > 0)) return s;
        s.wi = reflect(wo_world, n);
        const Real cos_i = glm::dot(s.wi, n);
        if (!(cos_i > 0)) return s;
        s.f = fresnel_conductor(cos_o, eta, k) / cos_i;
        s.pdf = 1;
        s.delta = true;
        return s;
    }
    const Frame frame = make_frame(n);
    const Vec3 wo = frame.to_local(wo_world);
    if (!(wo.z > 0)) return s;
    const Vec3 m = sample_ggx_visible_normal(wo, alpha, u);
    // Evaluated from the world direction it returns, as eval and pdf will see it: the same bits.
    const Vec3 world = glm::normalize(frame.to_world(2 * glm::dot(wo, m) * m - wo));
    const Scattering e = evaluate(wo, frame.to_local(world));
    if (!(e.pdf > 0)) return s;
    s.wi = world;
    s.f = f_of(e);
    s.pdf = e.pdf;
    return s;
}

}  // namespace rt
