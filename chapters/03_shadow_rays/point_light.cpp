#include "point_light.hpp"

namespace rt {

Color point_light_irradiance(const PointLight& light, const Vec3& p, const Vec3& n) {
    // EXERCISE(ch03.point_light) § Light from a point light
    const Vec3 to_light = light.position - p;
    const Real r2 = glm::dot(to_light, to_light);
    if (!(r2 > 0)) return Color(0);
    const Real cos_theta = glm::dot(n, to_light) / std::sqrt(r2);
    if (!(cos_theta > 0)) return Color(0);
    return light.intensity * (cos_theta / r2);
    // END EXERCISE
}

}  // namespace rt
