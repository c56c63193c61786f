// How a path leaves a surface in this chapter: along the mirror direction, or along one direction drawn
// uniformly from the hemisphere above a diffuse (or glossy) surface. Each gives the direction wi and the
// weight w = f(wo, wi) cos θ_i / p(wi) that multiplies the radiance L(wi) the next ray brings back:
//   L_r(wo) = ∫ f L cos θ_i dω_i ≈ w · L(wi).
// Directions point away from the surface; n is the unit normal on wo's side.
#pragma once

#include <optional>

#include "04_direct_lighting/brdf.hpp"
#include "04_direct_lighting/bsdf.hpp"
#include "rt/core/math.hpp"

namespace rt {

struct Scatter {
    Vec3 wi{0, 0, 1};  // unit
    Color weight{0};   // f cos θ_i / p
};

// The ideal mirror: wi = r(wo) = 2 (n · wo) n − wo and w = R (a delta BRDF: f cos / p is the reflectance).
// Nothing when r(wo) does not leave the surface (wo grazing: n · r <= 0 after rounding) or R is black.
std::optional<Scatter> mirror_scatter(const MirrorBrdf& mirror, const Vec3& wo, const Vec3& n);

// One direction uniform over the hemisphere around n (chapter 04's sample_uniform_hemisphere, p = 1 / (2π)),
// w = f(wo, wi) cos θ_i / p; for Lambert a closed form whose mean over the hemisphere is ρ.
// Nothing when the weight is 0 (wi in the tangent plane, or outside a lobe).
std::optional<Scatter> uniform_scatter(const Bsdf& brdf, const Vec3& wo, const Vec3& n, Vec2 u);

}  // namespace rt
