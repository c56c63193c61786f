// Ray–sphere intersection: |o + t d − c|² = r² with |d| = 1 is the quadratic t² + 2 b t + c₀ = 0, where
// f = o − c, b = f · d and c₀ = f · f − r². Two ways to solve it in float: the textbook one (kept for the
// lesson and the tests that show it failing) and the robust one the renderer uses.
#pragma once

#include <optional>

#include "rt/math.hpp"
#include "rt/ray.hpp"

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
// Ray Tracing Gems ch. 7), q = −(b + sign(b) √Δ), roots q and c₀ / q (no subtraction of near-equal numbers).
std::optional<SphereRoots> sphere_roots_stable(const Ray& ray, const Sphere& sphere);

// The nearest root in (0, t_max) of the robust form, if any.
std::optional<Real> intersect_sphere(const Ray& ray, const Sphere& sphere, Real t_max);

// Outward unit normal at a point p of the surface: (p − c) / r, renormalised.
Vec3 sphere_normal(const Sphere& sphere, const Vec3& p);

// Surface coordinates of the outward normal n: (phi / 2π, theta / π), phi = atan2(−n_z, n_x) + π,
// theta = acos(−n_y); finite at the poles.
Vec2 sphere_uv(const Vec3& n);

}  // namespace rt
