#include "coated_diffuse.hpp"

#include <algorithm>
#include <cmath>

#include "04_direct_lighting/brdf.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "fresnel.hpp"

namespace rt {

Real average_fresnel_outside(Real eta) {
    if (eta == 1) return 0;
    // In double: the terms are of order 1 and cancel to a few per cent.
    const double n = eta, n2 = n * n, n4 = n2 * n2;
    const double r =
        0.5 + (n - 1) * (3 * n + 1) / (6 * (n + 1) * (n + 1)) +
        n2 * (n2 - 1) * (n2 - 1) / ((n2 + 1) * (n2 + 1) * (n2 + 1)) * std::log((n - 1) / (n + 1)) -
        2 * n * n2 * (n2 + 2 * n - 1) / ((n2 + 1) * (n4 - 1)) +
        8 * n4 * (n4 + 1) / ((n2 + 1) * (n4 - 1) * (n4 - 1)) * std::log(n);
    return Real(r);
}

Real average_fresnel_inside(Real eta) {
    return 1 - (1 - average_fresnel_outside(eta)) / (eta * eta);
}

CoatedDiffuse::CoatedDiffuse(const Color& reflectance, Real eta_)
    : Bsdf({.diffuse = true, .black = is_black(reflectance) && eta_ == 1, .delta_lobe = true}), eta(eta_) {
    const Real inside = average_fresnel_inside(eta);
    base = reflectance / (kPi * eta * eta * (Color(1) - reflectance * inside));
    const Real mean = (reflectance.r + reflectance.g + reflectance.b) / 3;
    base_share = mean * (1 - inside) / (1 - mean * inside);
}

Color CoatedDiffuse::eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const {
    const Real cos_o = glm::dot(wo, n), cos_i = glm::dot(wi, n);
    if (!(cos_o > 0 && cos_i > 0)) return Color(0);
    return base * ((1 - fresnel_dielectric(cos_i, eta)) * (1 - fresnel_dielectric(cos_o, eta)));
}

Real CoatedDiffuse::coat_probability(Real cos_o) const {
    const Real F = fresnel_dielectric(cos_o, eta);
    const Real base_weight = (1 - F) * base_share;
    return base_weight > 0 ? F / (F + base_weight) : Real(1);
}

BsdfSample CoatedDiffuse::sample(const Vec3& wo, const Vec3& n, Vec2 u, Real) const {
    BsdfSample s;
    const Real cos_o = glm::dot(wo, n);
    if (!(cos_o > 0)) return s;  // pdf 0: nothing
    const Real coat = coat_probability(cos_o);
    if (u.x < coat) {
        s.wi = glm::normalize(reflect(wo, n));
        const Real cos_i = glm::dot(s.wi, n);
        s.f = cos_i > 0 ? Color(fresnel_dielectric(cos_o, eta) / (coat * cos_i)) : Color(0);
        s.pdf = 1;
        s.delta = true;
        return s;
    }
    // u.x, past the coat's share, is uniform again on [0, 1).
    u.x = std::min((u.x - coat) / (1 - coat), kOneMinusEpsilon);
    s.wi = glm::normalize(make_frame(n).to_world(sample_cosine_hemisphere(u)));
    s.f = eval(wo, s.wi, n);
    s.pdf = (1 - coat) * cosine_hemisphere_pdf(glm::dot(s.wi, n));
    return s;
}

Real CoatedDiffuse::pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const {
    const Real cos_o = glm::dot(wo, n);
    if (!(cos_o > 0)) return 0;
    return (1 - coat_probability(cos_o)) * cosine_hemisphere_pdf(glm::dot(wi, n));
}

}  // namespace rt
