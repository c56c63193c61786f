#include "quad.hpp"

namespace rt {

Quad make_quad(const Vec3& origin, const Vec3& u, const Vec3& v) {
    const Vec3 n = glm::cross(u, v);
    const Real n2 = glm::dot(n, n);
    if (!(n2 > 0)) return {origin, u, v, Vec3{0, 0, 1}, Vec3{0}, Vec3{0}};  // degenerate: zero axes mark it
    const Vec3 w = n / n2;
    return {origin, u, v, n / std::sqrt(n2), glm::cross(v, w), glm::cross(w, u)};
}

std::optional<QuadHit> intersect_quad(const Ray& ray, const Quad& quad, Real t_max) {
    // EXERCISE(ch02.quad)
    const Real denominator = glm::dot(quad.normal, ray.direction);
    if (denominator == 0 || quad.a_axis == Vec3{0}) return std::nullopt;
    const Real t = glm::dot(quad.normal, quad.origin - ray.origin) / denominator;
    if (!(t > 0 && t < t_max)) return std::nullopt;
    const Vec3 offset = ray.at(t) - quad.origin;
    const Real a = glm::dot(offset, quad.a_axis);
    const Real b = glm::dot(offset, quad.b_axis);
    if (!(a >= 0 && a <= 1 && b >= 0 && b <= 1)) return std::nullopt;
    return QuadHit{t, {a, b}};
    // END EXERCISE
}

}  // namespace rt
