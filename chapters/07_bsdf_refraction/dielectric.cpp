#include "dielectric.hpp"

#include <cmath>

#include "04_direct_lighting/brdf.hpp"
#include "fresnel.hpp"
#include "snell.hpp"

namespace rt {

DielectricSample sample_dielectric(const Vec3& wo, const Vec3& n, Real eta, Real u) {
    // EXERCISE(ch07.dielectric_sample) § The sampled dielectric
    const Real cos_o = glm::dot(n, wo);
    const Real R = fresnel_dielectric(cos_o, eta);
    if (u >= R) {
        // fresnel_dielectric is below 1 exactly when refract finds a direction (the same kTirCos2 test).
        if (const auto wt = refract(wo, n, eta)) {
            return {*wt, Color(1 / (eta * eta)), DielectricLobe::kTransmission, 1 - R};
        }
    }
    return {glm::normalize(reflect(wo, n)), Color(1), DielectricLobe::kReflection, R};
    // END EXERCISE
}

SmoothDielectric::SmoothDielectric(Real eta_, Transport transport_)
    : Bsdf({.delta = true, .transmission = true}), eta(eta_), transport(transport_) {}

BsdfSample SmoothDielectric::sample(const Vec3& wo, const Vec3& n, Vec2, Real u_lobe) const {
    const DielectricSample d = sample_dielectric(wo, n, eta, u_lobe);
    BsdfSample s;
    s.wi = d.wi;
    s.delta = true;
    s.pdf = 1;
    s.transmitted = d.lobe == DielectricLobe::kTransmission;
    const Color weight = transport == Transport::kImportance ? Color(1) : d.weight;
    // f |cos θ_i| / pdf = weight, the convention of every delta lobe (chapter 04's mirror).
    const Real cos_i = std::abs(glm::dot(d.wi, n));
    s.f = cos_i > 0 ? weight / cos_i : Color(0);
    // A transmission's weight is radiance's rescaling across the interface alone, which comes back when the
    // path leaves the glass: roulette leaves it out (bsdf.hpp).
    if (s.transmitted && transport == Transport::kRadiance) s.roulette_scale = d.weight.g;
    return s;
}

Color beer_lambert(const Color& absorption, Real distance) {
    // EXERCISE(ch07.beer_lambert) § Beer–Lambert: coloured glass
    Color t(1);
    for (int c = 0; c < 3; ++c) {
        if (absorption[c] > 0) t[c] = std::exp(-absorption[c] * distance);
    }
    return t;
    // END EXERCISE
}

}  // namespace rt
