// The warps chapter 04 does not have, each with its density: the whole sphere (for the sky), and points on a
// quad and a triangle (per unit area). Chapter 04's warps have theirs beside them in sampling.hpp. Directions
// are in the local frame of the warp (z the axis); a pdf is per unit solid angle (per unit area for points).
#pragma once

#include "rt/core/math.hpp"

namespace rt {

// Uniform over the whole sphere, pdf = 1 / (4π): by inversion of the distributions of z and of φ, with sin θ
// kept to its digits near the poles.
Vec3 sample_uniform_sphere(Vec2 u);
inline constexpr Real kUniformSpherePdf = Real(0.25) * kInvPi;

// A point of the parallelogram origin + a U + b V with (a, b) = u: pdf = 1 / |U × V| per unit area.
Vec3 sample_quad_point(const Vec3& origin, const Vec3& u_edge, const Vec3& v_edge, Vec2 u);
// A point of the triangle p0 p1 p2 from chapter 04's barycentrics b = sample_uniform_triangle(u):
// (1 − b1 − b2) p0 + b1 p1 + b2 p2; pdf = 1 / area.
Vec3 sample_triangle_point(const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec2 u);

}  // namespace rt
