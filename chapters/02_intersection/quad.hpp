// Ray–quad intersection. The parallelogram Q + a u + b v (a, b in [0, 1]) lies in the plane with normal
// n = u × v. The ray meets that plane where its point satisfies the plane's equation; the hit's coordinates
// (a, b) solve q = a u + b v for q = p − Q (the lesson derives them with cross products). make_quad computes
// once per quad the two vectors that turn q into a and b.
#pragma once

#include <optional>

#include "rt/core/math.hpp"
#include "rt/core/ray.hpp"

namespace rt {

struct Quad {
    Vec3 origin{0};
    Vec3 u{1, 0, 0};
    Vec3 v{0, 1, 0};
    Vec3 normal{0, 0, 1};  // unit u × v: the front side
    // The dual basis of (u, v) in the quad's plane (a_axis · u = 1, a_axis · v = 0, b_axis likewise), zero
    // for a degenerate quad.
    Vec3 a_axis{1, 0, 0};
    Vec3 b_axis{0, 1, 0};
};

Quad make_quad(const Vec3& origin, const Vec3& u, const Vec3& v);

struct QuadHit {
    Real t;
    Vec2 ab;  // the coordinates (a, b) of the hit point
};

// The hit with t in (0, t_max) and a, b in [0, 1], if any; a degenerate quad (u × v = 0) is never hit.
// Inline, like intersect_sphere: a call into another file returns the optional through memory, and reading it
// back costs a store-forwarding stall on every test (the lesson measures it).
inline std::optional<QuadHit> intersect_quad(const Ray& ray, const Quad& quad, Real t_max) {
    // EXERCISE(ch02.quad) § Each shape's equation
    const Real denominator = glm::dot(quad.normal, ray.direction);
    if (denominator == 0 || quad.a_axis == Vec3{0}) return std::nullopt;
    const Real t = glm::dot(quad.normal, quad.origin - ray.origin) / denominator;
    const Vec3 offset = ray.at(t) - quad.origin;
    const Real a = glm::dot(offset, quad.a_axis);
    const Real b = glm::dot(offset, quad.b_axis);
    // One test of all six conditions (& rather than &&): whether a random ray hits is unpredictable, and one
    // branch mispredicts less often than six.
    if (!((t > 0) & (t < t_max) & (a >= 0) & (a <= 1) & (b >= 0) & (b <= 1))) return std::nullopt;
    return QuadHit{t, {a, b}};
    // END EXERCISE
}

}  // namespace rt
