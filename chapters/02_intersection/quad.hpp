// Ray–quad intersection. The parallelogram Q + a u + b v (a, b in [0, 1]) lies in the plane with normal
// n = u × v; the ray meets that plane at t = n · (Q − o) / (n · d), and with p = o + t d and w = n / (n · n),
// a = w · ((p − Q) × v) = (p − Q) · (v × w) and b = w · (u × (p − Q)) = (p − Q) · (w × u): the vectors v × w and
// w × u are computed once per quad.
#pragma once

#include <optional>

#include "rt/math.hpp"
#include "rt/ray.hpp"

namespace rt {

struct Quad {
    Vec3 origin{0};
    Vec3 u{1, 0, 0};
    Vec3 v{0, 1, 0};
    Vec3 normal{0, 0, 1};  // unit u × v: the front side
    // The dual basis of (u, v) in the quad's plane: a = q · a_axis, b = q · b_axis for q = p − Q, where
    // a_axis = v × w and b_axis = w × u with w = n / (n · n) (zero for a degenerate quad).
    Vec3 a_axis{1, 0, 0};
    Vec3 b_axis{0, 1, 0};
};

Quad make_quad(const Vec3& origin, const Vec3& u, const Vec3& v);

struct QuadHit {
    Real t;
    Vec2 ab;  // the coordinates (a, b) of the hit point
};

// The hit with t in (0, t_max) and a, b in [0, 1], if any; a degenerate quad (u × v = 0) is never hit.
std::optional<QuadHit> intersect_quad(const Ray& ray, const Quad& quad, Real t_max);

}  // namespace rt
