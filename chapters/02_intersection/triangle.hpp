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

std::optional<TriangleHit> intersect_triangle_moller(const Ray& ray, const Triangle& triangle, Real t_max);

// Either test, by name (computes the watertight ray's shear itself).
std::optional<TriangleHit> intersect_triangle(const Ray& ray, const Triangle& triangle, Real t_max,
                                              TriangleTest test);

// The unit normal (p1 − p0) × (p2 − p0) / |...|: the front side is the side of counter-clockwise winding.
Vec3 triangle_normal(const Triangle& triangle);

}  // namespace rt
