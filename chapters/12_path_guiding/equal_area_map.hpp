// The cylindrical equal-area map between the unit sphere and the unit square (Lambert's cylinder, the map
// Practical Path Guiding stores its directional distributions in):
//   (u, v) = ((cos θ + 1) / 2, φ / 2π),   direction(u, v) = (r cos 2πv, r sin 2πv, 2u − 1), r = √(1 − z²).
// dω = sin θ dθ dφ = dz dφ = 2 du · 2π dv: every patch of the square covers 4π times its area of the sphere,
// so a density on the square is one on the sphere divided by the constant Jacobian 4π, and a quadtree's
// equal squares are equal solid angles.
#pragma once

#include <numbers>

#include "rt/core/math.hpp"

namespace rt {

// dω / (du dv): the solid angle per unit area of the square.
inline constexpr Real kEqualAreaJacobian = Real(4 * std::numbers::pi);

// The point of [0, 1)² of unit direction w (φ = atan2(y, x) taken in [0, 2π)).
Vec2 equal_area_point(const Vec3& w);
// The unit direction of point p of [0, 1]².
Vec3 equal_area_direction(Vec2 p);

}  // namespace rt
