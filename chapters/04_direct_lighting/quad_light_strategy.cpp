#include "quad_light_strategy.hpp"

#include <cmath>

#include "area_light_sampling.hpp"

namespace rt {

std::optional<SphericalRectangle> solid_angle_view(const QuadLight& light, const Vec3& p) {
    const Real lengths = glm::length(light.u) * glm::length(light.v);
    if (!(std::abs(glm::dot(light.u, light.v)) <= kRectangleCosine * lengths)) return std::nullopt;
    const auto view = SphericalRectangle::seen_from(p, light.origin, light.u, light.v);
    if (!view || !(view->solid_angle() >= kMinSphericalSolidAngle) ||
        !(view->solid_angle() <= kMaxSphericalSolidAngle))
        return std::nullopt;
    return view;
}

std::optional<LightSample> sample_quad_light_by_solid_angle(const QuadLight& light, const Vec3& p, Vec2 u) {
    const auto view = solid_angle_view(light, p);
    if (!view) return sample_quad_light(light, p, u);
    // The direction's point x = s + a U + b V, found by the area sampler at (a, b); its density is 1 / Ω.
    std::optional<LightSample> s = sample_quad_light(light, p, view->sample(u));
    if (s) s->pdf = Real(1 / view->solid_angle());
    return s;
}

Real quad_light_pdf(const QuadLight& light, const Vec3& p, const Vec3& wi, QuadLightSampling strategy) {
    const Real area_pdf = quad_light_pdf(light, p, wi);
    if (strategy == QuadLightSampling::kArea || !(area_pdf > 0)) return area_pdf;
    const auto view = solid_angle_view(light, p);
    return view ? Real(1 / view->solid_angle()) : area_pdf;
}

}  // namespace rt
