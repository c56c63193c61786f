// The shapes of the area lights: every shape whose material has an emission (light_set.hpp collects them).
// Area lights are one-sided: they emit on their front side (a quad: the side of u × v; a triangle:
// counter-clockwise; a sphere: outward). A two-sided quad or triangle (the material's "two_sided") emits on
// both: seen from a point, it is the one-sided light that faces the point (facing()).
#pragma once

#include "rt/core/math.hpp"

namespace rt {

// The parallelogram origin + a u + b v (a, b in [0, 1]) emitting radiance L on the side of normal = unit(u ×
// v).
struct QuadLight {
    Vec3 origin{0};
    Vec3 u{1, 0, 0};
    Vec3 v{0, 1, 0};
    Vec3 normal{0, 0, 1};
    Real area = 1;  // |u × v|
    Color radiance{1};
    bool two_sided = false;
};

// The triangle p0 p1 p2 emitting on the side of normal = unit((p1 − p0) × (p2 − p0)).
struct TriangleLight {
    Vec3 p0{0};
    Vec3 p1{1, 0, 0};
    Vec3 p2{0, 1, 0};
    Vec3 normal{0, 0, 1};
    Real area = Real(0.5);
    Color radiance{1};
    bool two_sided = false;
};

struct SphereLight {
    Vec3 center{0};
    Real radius = 1;
    Color radiance{1};
};

// The emitting area of a light: |u × v| for a quad, half that for a triangle, 4π r² for a sphere.
inline Real area_of(const QuadLight& q) {
    return q.area;
}
inline Real area_of(const TriangleLight& t) {
    return t.area;
}
inline Real area_of(const SphereLight& s) {
    return 4 * kPi * s.radius * s.radius;
}

// How many sides emit: 1, or 2 for a two-sided light (its power is twice a one-sided one's).
inline Real sides(const QuadLight& q) {
    return q.two_sided ? 2 : 1;
}
inline Real sides(const TriangleLight& t) {
    return t.two_sided ? 2 : 1;
}

// The one-sided light that p sees: the light itself, or for a two-sided light behind p its back turned to
// the front (a quad with u and v swapped, a triangle with p1 and p2: the same points, the normal negated).
QuadLight facing(const QuadLight& q, const Vec3& p);
TriangleLight facing(const TriangleLight& t, const Vec3& p);

QuadLight make_quad_light(const Vec3& origin, const Vec3& u, const Vec3& v, const Color& radiance);
TriangleLight make_triangle_light(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Color& radiance);

}  // namespace rt
