#include "sphere.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

std::optional<SphereRoots> sphere_roots_textbook(const Ray& ray, const Sphere& sphere) {
    // EXERCISE(ch02.sphere_textbook) § Each shape's equation
    const Vec3 f = ray.origin - sphere.center;
    const Real b = glm::dot(f, ray.direction);
    const Real c = glm::dot(f, f) - sphere.radius * sphere.radius;
    const Real discriminant = b * b - c;
    if (discriminant < 0) return std::nullopt;
    const Real root = std::sqrt(discriminant);
    return SphereRoots{-b - root, -b + root};
    // END EXERCISE
}

Vec3 sphere_normal(const Sphere& sphere, const Vec3& p) {
    const Vec3 n = (p - sphere.center) / sphere.radius;
    const Real length = glm::length(n);
    return length > 0 ? n / length : Vec3{0, 1, 0};
}

Vec2 sphere_uv(const Vec3& n) {
    Real phi = std::atan2(n.z, n.x);
    if (phi < 0) phi += 2 * kPi;
    const Real theta = std::acos(std::clamp(n.y, Real(-1), Real(1)));
    return {phi / (2 * kPi), 1 - theta / kPi};
}

}  // namespace rt
