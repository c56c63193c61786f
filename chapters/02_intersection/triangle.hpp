// Ray–triangle intersection, two ways. A point of the triangle is b0 p0 + b1 p1 + b2 p2 with barycentrics
// b0 + b1 + b2 = 1, all >= 0.
//  - Möller–Trumbore (1997): solve o + t d = p0 + b1 e1 + b2 e2 (e1 = p1 − p0, e2 = p2 − p0) by Cramer's
//  rule.
//    Each triangle computes its own edge tests, so a ray through an edge shared by two triangles can be
//    rounded outside both: it leaks.
//  - Watertight (Woop, Benthin, Wald 2013): move the ray's origin to 0, permute the axes so the ray's largest
//    component is z, and shear so the ray is the z axis. Each edge function then depends only on the edge's
//    two (sheared) vertices, computed the same way for both triangles sharing it, so the signs agree: no ray
//    falls between them.
#pragma once

#include <optional>

#include "float_error.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/core/math.hpp"
#include "rt/core/ray.hpp"

namespace rt {

enum class TriangleTest { kWatertight, kMollerTrumbore };

constexpr auto names_of(TriangleTest) {
    return enum_names<TriangleTest>("--triangle-test",
                                    {{TriangleTest::kWatertight, "watertight"}, {TriangleTest::kMollerTrumbore, "moller"}});
}

struct Triangle {
    Vec3 p0{0};
    Vec3 p1{0};
    Vec3 p2{0};
};

struct TriangleHit {
    Real t;
    Vec2 barycentrics;  // (b1, b2): the weights of p1 and p2
};

// What the watertight test computes once per ray: the permutation (kx, ky, kz) with |d_kz| largest (kx, ky
// swapped when d_kz < 0, to keep the winding), and the shear S = (d_kx / d_kz, d_ky / d_kz, 1 / d_kz):
// a point (x, y, z) of the permuted frame becomes (x − S_x z, y − S_y z, S_z z), the ray (0, 0, t).
struct WatertightRay {
    int kx, ky, kz;
    Real sx, sy, sz;
};

WatertightRay make_watertight_ray(const Ray& ray);

std::optional<TriangleHit> intersect_triangle_watertight(const Ray& ray, const WatertightRay& sheared,
                                                         const Triangle& triangle, Real t_max);

// The bound δt on the rounding error of the watertight test's t (PBRT 4 §6.8.7), from the largest sheared
// coordinates |x'|, |y'|, |z'|, the largest edge function and |1 / det|: for a Real, a packet's lanes or a
// double, by the same operations.
template <typename T>
T watertight_distance_bound(const T& max_x, const T& max_y, const T& max_z, const T& max_e,
                            const T& inverse_abs) {
    const T delta_z = gamma_bound(3) * max_z;
    const T delta_x = gamma_bound(5) * (max_x + max_z), delta_y = gamma_bound(5) * (max_y + max_z);
    const T delta_e = 2 * (gamma_bound(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    return 3 * (gamma_bound(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * inverse_abs;
}

// Below this, the scaled distance T = U z'_a + V z'_b + W z'_c (a product of three coordinates) may have been
// rounded among float's subnormals, where an error is absolute, not relative, and δt no longer bounds t: a
// triangle within about 10⁻¹³ of the ray's origin. Such a hit is decided again in double.
inline constexpr Real kSmallestScaledDistance = 0x1p-90f;

// The watertight test's last step in double, from its float edge functions (U, V, W) and sheared corners
// (x', y', z' of a, b, c): the hit if t lies in (δt, t_max). Products of floats are exact in double, and no
// product of the course's coordinates underflows there.
std::optional<TriangleHit> watertight_hit_in_double(const Vec3& edge, const Vec3& x, const Vec3& y,
                                                    const Vec3& z, Real t_max);

std::optional<TriangleHit> intersect_triangle_moller(const Ray& ray, const Triangle& triangle, Real t_max);

// Either test, by name (computes the watertight ray's shear itself).
std::optional<TriangleHit> intersect_triangle(const Ray& ray, const Triangle& triangle, Real t_max,
                                              TriangleTest test);

// The unit normal (p1 − p0) × (p2 − p0) / |...|: the front side is the side of counter-clockwise winding.
Vec3 triangle_normal(const Triangle& triangle);

}  // namespace rt
