// A point light seen from p: a delta, so its one direction wi = (x − p) / d carries E = I cos θ / d², i.e.
// L_e / pdf = I / d² with pdf 1 by convention. Nothing when p is at the light.
#pragma once

#include <cmath>
#include <optional>

#include "light_sample.hpp"
#include "rt/core/scene.hpp"

namespace rt {

inline std::optional<LightSample> sample_point_light(const PointLight& light, const Vec3& p) {
    const Vec3 to_light = light.position - p;
    const Real d2 = glm::dot(to_light, to_light);
    if (!(d2 > 0)) return std::nullopt;
    const Real d = std::sqrt(d2);
    return LightSample{light.position, to_light / d, d, light.intensity / d2, 1};
}

}  // namespace rt
