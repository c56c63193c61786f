#include "sphere.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

std::optional<SphereRoots> sphere_roots_textbook(const Ray& ray, const Sphere& sphere) {
    // EXERCISE(ch02.sphere_textbook)
    const Vec3 f = ray.origin - sphere.center;
    const Real b = glm::dot(f, ray.direction);
    const Real c = glm::dot(f, f) - sphere.radius * sphere.radius;
    const Real discriminant = b * b - c;
    if (discriminant < 0) return std::nullopt;
    const Real root = std::sqrt(discriminant);
    return SphereRoots{-b - root, -b + root};
    // END EXERCISE
}

std::optional<SphereRoots> sphere_roots_stable(const Ray& ray, const Sphere& sphere) {
    // EXERCISE(ch02.sphere_stable)
    const Vec3 f = ray.origin - sphere.center;
    const Vec3& d = ray.direction;
    const Real b = glm::dot(f, d);
    // f − b d, the centre's offset from the line, with one rounding per component (fma): it is small when
    // the sphere is small, and computing it directly avoids subtracting b² from |f|².
    const Vec3 perpendicular{std::fma(-b, d.x, f.x), std::fma(-b, d.y, f.y), std::fma(-b, d.z, f.z)};
    const Real r = sphere.radius;
    const Real distance = glm::length(perpendicular);
    const Real discriminant = (r - distance) * (r + distance);
    if (discriminant < 0) return std::nullopt;
    // c₀ = |f|² − r² in double: products of floats are exact in double, so only the final rounding remains
    // (in float it cancels when the origin is near a large sphere's surface).
    const Vec3d fd{f};
    const Real c = Real(glm::dot(fd, fd) - double(r) * double(r));
    const Real q = -(b + std::copysign(std::sqrt(discriminant), b));
    if (q == 0) return SphereRoots{0, 0};  // the origin is on the surface and the ray is tangent to it
    const Real t0 = c / q;
    return SphereRoots{std::min(q, t0), std::max(q, t0)};
    // END EXERCISE
}

std::optional<Real> intersect_sphere(const Ray& ray, const Sphere& sphere, Real t_max) {
    const auto roots = sphere_roots_stable(ray, sphere);
    if (!roots) return std::nullopt;
    if (roots->t0 > 0 && roots->t0 < t_max) return roots->t0;
    if (roots->t1 > 0 && roots->t1 < t_max) return roots->t1;
    return std::nullopt;
}

Vec3 sphere_normal(const Sphere& sphere, const Vec3& p) {
    const Vec3 n = (p - sphere.center) / sphere.radius;
    const Real length = glm::length(n);
    return length > 0 ? n / length : Vec3{0, 1, 0};
}

Vec2 sphere_uv(const Vec3& n) {
    const Real phi = std::atan2(-n.z, n.x) + kPi;
    const Real theta = std::acos(std::clamp(-n.y, Real(-1), Real(1)));
    return {phi / (2 * kPi), theta / kPi};
}

}  // namespace rt
