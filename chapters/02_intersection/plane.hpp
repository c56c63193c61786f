// Ray–plane intersection: the plane {p : n · (p − p₀) = 0} meets o + t d at t = n · (p₀ − o) / (n · d).
#pragma once

#include <optional>

#include "rt/core/math.hpp"
#include "rt/core/ray.hpp"

namespace rt {

struct Plane {
    Vec3 point{0};
    Vec3 normal{0, 1, 0};   // unit, outward (the front side)
    Vec3 tangent{1, 0, 0};  // unit, in the plane: uv = ((p − p₀) · tangent, (p − p₀) · bitangent)
    Vec3 bitangent{0, 0, 1};
};

// A plane through `point` with outward normal `normal` (normalised here), and a tangent basis for its uv.
Plane make_plane(const Vec3& point, const Vec3& normal);

// t in (0, t_max), or nothing when the ray is parallel to the plane (n · d = 0) or meets it outside.
std::optional<Real> intersect_plane(const Ray& ray, const Plane& plane, Real t_max);

// Coordinates of a point of the plane in its tangent basis.
Vec2 plane_uv(const Plane& plane, const Vec3& p);

}  // namespace rt
