#include "plane.hpp"

#include <cmath>

namespace rt {

Plane make_plane(const Vec3& point, const Vec3& normal) {
    const Vec3 n = glm::normalize(normal);
    // A tangent from the axis least aligned with n, so the cross product is never small.
    const Vec3 axis = std::abs(n.x) < Real(0.5) ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 tangent = glm::normalize(glm::cross(axis, n));
    return {point, n, tangent, glm::cross(n, tangent)};
}

std::optional<Real> intersect_plane(const Ray& ray, const Plane& plane, Real t_max) {
    // EXERCISE(ch02.plane) § Each shape's equation
    const Real denominator = glm::dot(plane.normal, ray.direction);
    if (denominator == 0) return std::nullopt;
    const Real t = glm::dot(plane.normal, plane.point - ray.origin) / denominator;
    if (!(t > 0 && t < t_max)) return std::nullopt;  // also refuses a NaN
    return t;
    // END EXERCISE
}

Vec2 plane_uv(const Plane& plane, const Vec3& p) {
    const Vec3 offset = p - plane.point;
    return {glm::dot(offset, plane.tangent), glm::dot(offset, plane.bitangent)};
}

Vec2d plane_texture_uv(const Plane& plane, const Ray& ray, Real t) {
    const Vec3d offset = Vec3d(ray.origin) - Vec3d(plane.point) + double(t) * Vec3d(ray.direction);
    return {glm::dot(offset, Vec3d(plane.tangent)), glm::dot(offset, Vec3d(plane.bitangent))};
}

}  // namespace rt
