// Ray–sphere intersection: |o + t d − c|² = r² with |d| = 1 is the quadratic t² + 2 b t + c₀ = 0, where
// f = o − c, b = f · d and c₀ = f · f − r². Two ways to solve it in float: the textbook one (kept for the
// lesson and the tests that show it failing) and the robust one the renderer uses.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "rt/core/math.hpp"
#include "rt/core/ray.hpp"

namespace rt {

struct Sphere {
    Vec3 center{0};
    Real radius = 1;
};

// The two roots t0 <= t1 of the ray's quadratic, or nothing when the ray misses the sphere's surface.
struct SphereRoots {
    Real t0;
    Real t1;
};

// Textbook: Δ = b² − c₀, t = −b ∓ √Δ. Both steps cancel: b² − c₀ loses every digit when the sphere is small
// and far (b² ≫ Δ), and −b + √Δ loses them when the origin is near the surface (|b| ≈ √Δ).
std::optional<SphereRoots> sphere_roots_textbook(const Ray& ray, const Sphere& sphere);

// Robust: Δ = r² − |f − b d|² (the perpendicular distance from the centre to the line, Hearn & Baker;
// Ray Tracing Gems ch. 7), q = −(b + sign(b) √Δ) one root, the other from the product of the roots (Vieta):
// no subtraction of near-equal numbers.
inline std::optional<SphereRoots> sphere_roots_stable(const Ray& ray, const Sphere& sphere) {
    // EXERCISE(ch02.sphere_stable) § Each shape's equation
    const Vec3 f = ray.origin - sphere.center;
    const Vec3& d = ray.direction;
    const Real b = glm::dot(f, d);
    // f − b d, the centre's offset from the line, in double: a product of two floats is exact in double, so
    // each component is rounded once. It is small when the sphere is small, and computing it directly avoids
    // subtracting b² from |f|².
    const Vec3d fd{f};
    const Vec3 perpendicular{fd - double(b) * Vec3d{d}};
    const Real r = sphere.radius;
    const Real distance = glm::length(perpendicular);
    const Real discriminant = (r - distance) * (r + distance);
    if (discriminant < 0) return std::nullopt;
    // c₀ = |f|² − r² in double, for the same reason: only the final rounding remains (in float it cancels when
    // the origin is near a large sphere's surface).
    const Real c = Real(glm::dot(fd, fd) - double(r) * double(r));
    const Real q = -(b + std::copysign(std::sqrt(discriminant), b));
    if (q == 0) return SphereRoots{0, 0};  // the origin is on the surface and the ray is tangent to it
    const Real t0 = c / q;
    return SphereRoots{std::min(q, t0), std::max(q, t0)};
    // END EXERCISE
}

// The nearest root in (0, t_max) of the robust form, if any. Inline, with sphere_roots_stable: called from
// another file, the optional would come back through memory and stall each test (see intersect_quad).
inline std::optional<Real> intersect_sphere(const Ray& ray, const Sphere& sphere, Real t_max) {
    const auto roots = sphere_roots_stable(ray, sphere);
    if (!roots) return std::nullopt;
    if (roots->t0 > 0 && roots->t0 < t_max) return roots->t0;
    if (roots->t1 > 0 && roots->t1 < t_max) return roots->t1;
    return std::nullopt;
}

// Outward unit normal at a point p of the surface: (p − c) / r, renormalised.
Vec3 sphere_normal(const Sphere& sphere, const Vec3& p);
// Texture coordinates at the point of outward unit normal n: pbrt's spherical (φ, θ) parametrisation with the
// scene's y as the pole, u = φ / 2π with φ = atan2(n_z, n_x) in [0, 2π), v = 1 − θ / π with θ = acos(n_y):
// v = 0 at the bottom pole, 1 at the top.
Vec2 sphere_uv(const Vec3& n);

}  // namespace rt
