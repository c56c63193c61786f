// Warps: uniform random points u in [0, 1)² turned into directions or points with a known density (pdf),
// each beside its density. A sampler is only half of an estimator: f / pdf needs the density of the very
// direction drawn, and MIS (chapter 06) needs the density of a direction some other sampler drew. Directions
// are in a local frame whose z axis is the axis of the distribution (see frame.hpp); a pdf is per unit solid
// angle.
#pragma once

#include <algorithm>

#include "rt/core/math.hpp"

namespace rt {

// Uniform over the hemisphere z > 0, pdf = 1 / (2π): by inversion of the distributions of z and of φ.
Vec3 sample_uniform_hemisphere(Vec2 u);
inline constexpr Real kUniformHemispherePdf = Real(0.5) * kInvPi;
// Its density at w: 1 / (2π) for z >= 0, else 0 (z = u₁ reaches z = 0 at u₁ = 0: the horizon belongs to the
// support).
Real uniform_hemisphere_pdf(const Vec3& w);

// Cosine-weighted over the hemisphere, pdf = cos θ / π = z / π, by Malley's method: a uniform point of the
// unit disc (by inversion of the distribution of its radius) lifted straight up to the hemisphere.
Vec3 sample_cosine_hemisphere(Vec2 u);
// Its density at a direction whose cosine to the axis is cos θ (w.z in the local frame, n · wi in the
// world): max(0, cos θ) / π. The one place the course writes it (Lambert's BRDF, the sky's light samples).
inline Real cosine_hemisphere_pdf(Real cos_theta) {
    return std::max(Real(0), cos_theta) * kInvPi;
}

// Uniform over the cone of directions within θmax of the z axis, given one_minus_cos_max = 1 − cos θmax
// (passed as such so a narrow cone keeps its digits), pdf = 1 / (2π (1 − cos θmax)): by inversion of the
// distribution of 1 − cos θ, solved for 1 − cos θ itself (and sin θ from it) so a narrow cone keeps its digits.
Vec3 sample_uniform_cone(Vec2 u, Real one_minus_cos_max);
// Its density at w: 1 / (2π (1 − cos θmax)) for 1 − z <= 1 − cos θmax, else 0.
Real uniform_cone_pdf(const Vec3& w, Real one_minus_cos_max);

// The power-cosine lobe around z, a density proportional to cos^e α (power_cosine_pdf): by inversion of the
// distribution of cos α, with 1 − cos α and sin α kept to their digits when e is in the thousands.
Vec3 sample_power_cosine(Vec2 u, Real exponent);
// Its density at a direction whose cosine to the lobe's axis is cos α: c cos^e α for cos α > 0, else 0, with
// c the constant for which it integrates to 1 over the hemisphere (the glossy and retro-reflective BRDFs' pdf).
Real power_cosine_pdf(Real cos_alpha, Real exponent);

// Uniform over a triangle, as barycentrics (b1, b2) of p1 and p2 (pdf = 1 / area; density 2 over b1 + b2 <= 1):
// by inversion of the marginal distribution of b1, then of b2 given b1.
Vec2 sample_uniform_triangle(Vec2 u);

}  // namespace rt
