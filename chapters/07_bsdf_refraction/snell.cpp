#include "snell.hpp"

#include <cmath>

#include "fresnel.hpp"

namespace rt {

std::optional<Vec3> refract(const Vec3& wo, const Vec3& n, Real eta) {
    // EXERCISE(ch07.refract) § Snell's law
    Real cos_i = glm::dot(n, wo);
    const Vec3 normal = cos_i < 0 ? -n : n;
    face_incident_side(cos_i, eta);
    const Real cos2_t = cos2_transmitted(cos_i, eta);
    if (cos2_t <= kTirCos2) return std::nullopt;
    const Vec3 wt = -wo / eta + (cos_i / eta - std::sqrt(cos2_t)) * normal;
    return glm::normalize(wt);
    // END EXERCISE
}

}  // namespace rt
