// The Henyey–Greenstein phase function (Henyey & Greenstein 1941): one parameter, the asymmetry g in (−1, 1),
// which is its mean cosine. With θ the angle between the direction the path travelled in (−wo) and the
// direction it scatters into (wi), cos θ = −wo · wi:
//   p(cos θ) = (1 / 4π) (1 − g²) / (1 + g² − 2 g cos θ)^(3/2),
// isotropic (1 / 4π) at g = 0, peaked forward for g > 0 (milk, fog: g ≈ 0.7–0.9) and backward for g < 0.
// Its cumulative distribution inverts in closed form, so sampling is exact: p / pdf = 1.
#pragma once

#include "phase_function.hpp"
#include "rt/core/math.hpp"

namespace rt {

// p(cos θ) for asymmetry g. The denominator is written (1 − g)² + 2 g (1 − cos θ), in double: at g = 0.999
// and cos θ = 1 the textbook 1 + g² − 2 g cos θ loses every digit to cancellation.
Real henyey_greenstein(Real cos_theta, Real g);

// cos θ drawn with density 2π p(cos θ) from u in [0, 1), by inversion of its cumulative distribution (the
// isotropic one for |g| < 1e-3, where the general one divides by nearly 0), clamped to [−1, 1].
Real sample_henyey_greenstein_cos(Real g, Real u);

class HenyeyGreenstein final : public PhaseFunction {
  public:
    explicit HenyeyGreenstein(Real g_) : g(g_) {}
    Real eval(const Vec3& wo, const Vec3& wi) const override;
    PhaseSample sample(const Vec3& wo, Vec2 u) const override;
    Real pdf(const Vec3& wo, const Vec3& wi) const override { return eval(wo, wi); }

    Real g;
};

}  // namespace rt
