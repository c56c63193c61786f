// Warps: uniform random points u in [0, 1)² turned into directions or points with a known density (pdf),
// each beside its density. A sampler is only half of an estimator: f / pdf needs the density of the very
// direction drawn, and MIS (chapter 06) needs the density of a direction some other sampler drew. Directions
// are in a local frame whose z axis is the axis of the distribution (see frame.hpp); a pdf is per unit solid
// angle.
#pragma once

#include <algorithm>

#include "rt/core/math.hpp"

namespace rt {

// Uniform over the hemisphere z > 0: z = u₁, φ = 2π u₂; pdf = 1 / (2π).
Vec3 sample_uniform_hemisphere(Vec2 u);
inline constexpr Real kUniformHemispherePdf = Real(0.5) * kInvPi;
// Its density at w: 1 / (2π) for z >= 0, else 0 (z = u₁ reaches z = 0 at u₁ = 0: the horizon belongs to the
// support).
Real uniform_hemisphere_pdf(const Vec3& w);

// Cosine-weighted over the hemisphere (Malley: a uniform point of the unit disc lifted to the hemisphere):
// r = √u₁, φ = 2π u₂, z = √(1 − u₁); pdf = cos θ / π = z / π.
Vec3 sample_cosine_hemisphere(Vec2 u);
// Its density at a direction whose cosine to the axis is cos θ (w.z in the local frame, n · wi in the
// world): max(0, cos θ) / π. The one place the course writes it (Lambert's BRDF, the sky's light samples).
inline Real cosine_hemisphere_pdf(Real cos_theta) {
    return std::max(Real(0), cos_theta) * kInvPi;
}

// Uniform over the cone of directions within θmax of the z axis, given one_minus_cos_max = 1 − cos θmax
// (passed as such so a narrow cone keeps its digits): 1 − cos θ = u₁ (1 − cos θmax), φ = 2π u₂;
// pdf = 1 / (2π (1 − cos θmax)).
Vec3 sample_uniform_cone(Vec2 u, Real one_minus_cos_max);
// Its density at w: 1 / (2π (1 − cos θmax)) for 1 − z <= 1 − cos θmax, else 0.
Real uniform_cone_pdf(const Vec3& w, Real one_minus_cos_max);

// The power-cosine lobe around z: cos α = (1 − u₁)^(1 / (e + 1)), φ = 2π u₂; pdf = (e + 1) / (2π) cos^e α.
Vec3 sample_power_cosine(Vec2 u, Real exponent);
// Its density at a direction whose cosine to the lobe's axis is cos α: (e + 1) / (2π) cos^e α for cos α > 0,
// else 0 (the glossy and retro-reflective BRDFs' pdf).
Real power_cosine_pdf(Real cos_alpha, Real exponent);

// Uniform over a triangle, as barycentrics (b1, b2) of p1 and p2: b1 = 1 − √u₁, b2 = u₂ √u₁; pdf = 1 / area.
Vec2 sample_uniform_triangle(Vec2 u);

}  // namespace rt
