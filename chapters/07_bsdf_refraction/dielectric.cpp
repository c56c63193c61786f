#include "dielectric.hpp"

#include <cmath>

#include "brdf.hpp"
#include "fresnel.hpp"
#include "snell.hpp"

namespace rt {

DielectricSample sample_dielectric(const Vec3& wo, const Vec3& n, Real eta, Real u) {
    // EXERCISE(ch07.dielectric_sample)
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

Color beer_lambert(const Color& absorption, Real distance) {
    // EXERCISE(ch07.beer_lambert)
    Color t(1);
    for (int c = 0; c < 3; ++c) {
        if (absorption[c] > 0) t[c] = std::exp(-absorption[c] * distance);
    }
    return t;
    // END EXERCISE
}

}  // namespace rt
