#include "area_light_sampling.hpp"

#include <cmath>

#include "02_intersection/float_error.hpp"
#include "sampling.hpp"

namespace rt {
namespace {

// The sample toward x (within `error` of the light's plane) on a one-sided planar light with unit normal n
// and area A.
std::optional<LightSample> toward(const Vec3& x, const Vec3& error, const Vec3& n, Real area,
                                  const Color& radiance, const Vec3& p) {
    const Vec3 to_light = x - p;
    const Real distance = glm::length(to_light);
    if (!(distance > 0)) return std::nullopt;
    const Vec3 wi = to_light / distance;
    const Real cos_light = -glm::dot(n, wi);  // > 0 when p is on the emitting side
    if (!(cos_light > 0)) return std::nullopt;
    const Real pdf = area_to_solid_angle_pdf(distance, cos_light, area);
    if (!std::isfinite(pdf)) return std::nullopt;
    return LightSample{x, wi, distance, radiance, pdf, n, error};
}

}  // namespace

std::optional<LightSample> sample_quad_light(const QuadLight& light, const Vec3& p, Vec2 u) {
    // EXERCISE(ch04.sample_quad_light) § Sampling the lights
    const Vec3 along_u = u.x * light.u, along_v = u.y * light.v;
    const Vec3 x = light.origin + along_u + along_v;
    const Vec3 error = gamma_bound(3) * (abs(light.origin) + abs(along_u) + abs(along_v));
    return toward(x, error, light.normal, light.area, light.radiance, p);
    // END EXERCISE
}

Real quad_light_pdf(const QuadLight& light, const Vec3& p, const Vec3& wi) {
    const Real denominator = glm::dot(light.normal, wi);
    if (!(denominator < 0)) return 0;  // parallel, or toward the back of the light
    const Real t = glm::dot(light.normal, light.origin - p) / denominator;
    if (!(t > 0)) return 0;
    // The hit's coordinates a = ((x − o) × V) · n / |U × V|, b = (U × (x − o)) · n / |U × V|.
    const Vec3 rel = p + t * wi - light.origin;
    const Real a = glm::dot(glm::cross(rel, light.v), light.normal) / light.area;
    const Real b = glm::dot(glm::cross(light.u, rel), light.normal) / light.area;
    if (a < 0 || a > 1 || b < 0 || b > 1) return 0;
    return area_to_solid_angle_pdf(t, -denominator, light.area);
}

std::optional<LightSample> sample_triangle_light(const TriangleLight& light, const Vec3& p, Vec2 u) {
    const Vec2 b = sample_uniform_triangle(u);
    const Vec3 w0 = (1 - b.x - b.y) * light.p0, w1 = b.x * light.p1, w2 = b.y * light.p2;
    const Vec3 error = gamma_bound(7) * (abs(w0) + abs(w1) + abs(w2));
    return toward(w0 + w1 + w2, error, light.normal, light.area, light.radiance, p);
}

}  // namespace rt
