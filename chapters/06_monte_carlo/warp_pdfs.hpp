// The density that goes with each warp of chapter 04's sampling.hpp, and the warps chapter 04 does not have
// (the whole sphere). A sampler is only half of an estimator: f / pdf needs the density of the very
// direction drawn, and MIS needs the density of a direction some other sampler drew. Directions are in the
// local frame of the warp (z the axis); a pdf is per unit solid angle (per unit area for points).
#pragma once

#include "rt/math.hpp"

namespace rt {

// Uniform over the whole sphere: z = 1 − 2 u₁, φ = 2π u₂; pdf = 1 / (4π).
Vec3 sample_uniform_sphere(Vec2 u);
inline constexpr Real kUniformSpherePdf = Real(0.25) * kInvPi;

// sample_uniform_hemisphere: pdf = 1 / (2π) for z >= 0, else 0. (Chapter 04's z = u₁ reaches z = 0 at u₁ = 0:
// the horizon belongs to the support.)
Real uniform_hemisphere_pdf(const Vec3& w);
// sample_cosine_hemisphere: pdf = cos θ / π = max(0, z) / π.
Real cosine_hemisphere_pdf(const Vec3& w);
// sample_uniform_cone: pdf = 1 / (2π (1 − cos θmax)) for 1 − z <= 1 − cos θmax, else 0.
Real uniform_cone_pdf(const Vec3& w, Real one_minus_cos_max);
// sample_power_cosine: pdf = (e + 1) / (2π) z^e for z >= 0, else 0.
Real power_cosine_pdf(const Vec3& w, Real exponent);

// A point of the parallelogram origin + a U + b V with (a, b) = u: pdf = 1 / |U × V| per unit area.
Vec3 sample_quad_point(const Vec3& origin, const Vec3& u_edge, const Vec3& v_edge, Vec2 u);
// A point of the triangle p0 p1 p2 from chapter 04's barycentrics b = sample_uniform_triangle(u):
// (1 − b1 − b2) p0 + b1 p1 + b2 p2; pdf = 1 / area.
Vec3 sample_triangle_point(const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec2 u);

}  // namespace rt
