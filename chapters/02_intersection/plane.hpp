// Ray–plane intersection: the plane {p : n · (p − p₀) = 0} meets o + t d where o + t d satisfies its equation.
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

// Float's hit point holds a plane's coordinates only to float's steps there, which grow with the distance
// from the origin: 2 units at 3·10⁷, where a checker of unit squares would come out one colour. A ray that
// starts farther than this from the origin takes its texture coordinates from plane_texture_uv instead.
inline constexpr Real kFarFromOrigin = 65536;  // 2^16: float's steps are 2^-7 of a unit here

// The texture coordinates of ray.at(t) on the plane, to float's precision of the distance t rather than of
// the point: (o − p₀ + t d) · (tangent, bitangent), in double from the ray's origin as float holds it.
Vec2d plane_texture_uv(const Plane& plane, const Ray& ray, Real t);

}  // namespace rt
