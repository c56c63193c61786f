// Sampling a sphere light by solid angle (cone sampling). From p at distance d from the centre, a sphere of
// radius r fills the cone of half-angle θmax around the direction to its centre, sin θmax = r / d. Drawing
// directions uniformly in that cone wastes none on the sphere's far side:
//   pdf = 1 / Ω,   Ω = 2π (1 − cos θmax)   (the cone's solid angle).
// Far away, cos θmax = √(1 − r²/d²) rounds to 1 in float and 1 − cos θmax to 0 (Ω = 0, pdf = ∞). The stable
// form never subtracts: 1 − cos θmax = sin² θmax / (1 + cos θmax).
#pragma once

#include <optional>

#include "area_lights.hpp"
#include "light_sample.hpp"

namespace rt {

// 1 − cos θmax from sin²θmax (cos θmax = √(1 − sin²θmax)), without subtracting two numbers close to 1.
Real one_minus_cos_stable(Real sin2_max);
// The textbook 1 − √(1 − sin²θmax): cancels to 0 once sin²θmax < 2⁻²⁴ (kept for the test that shows it).
Real one_minus_cos_naive(Real sin2_max);

// 1 / (2π (1 − cos θmax)) when p is outside the sphere, 0 inside (the light emits outward only).
Real sphere_light_pdf(const SphereLight& light, const Vec3& p);

// A direction in the cone, and the point where it meets the sphere; nothing when p is inside it.
std::optional<LightSample> sample_sphere_light(const SphereLight& light, const Vec3& p, Vec2 u);

}  // namespace rt
