#include "sampling.hpp"

#include <algorithm>
#include <cmath>

namespace rt {
namespace {

// The unit vector at polar angle θ (given cos θ and sin θ) and azimuth 2π u.
Vec3 spherical(Real cos_theta, Real sin_theta, Real u) {
    const Real phi = 2 * kPi * u;
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

}  // namespace

Vec3 sample_uniform_hemisphere(Vec2 u) {
    // EXERCISE(ch04.uniform_hemisphere) § Four BRDFs
    const Real z = u.x;
    return spherical(z, std::sqrt(std::max(Real(0), 1 - z * z)), u.y);
    // END EXERCISE
}

Vec3 sample_cosine_hemisphere(Vec2 u) {
    // EXERCISE(ch04.cosine_hemisphere) § Four BRDFs
    const Real r = std::sqrt(u.x);
    return spherical(std::sqrt(std::max(Real(0), 1 - u.x)), r, u.y);
    // END EXERCISE
}

Vec3 sample_uniform_cone(Vec2 u, Real one_minus_cos_max) {
    // EXERCISE(ch04.uniform_cone) § Sampling the lights
    const Real one_minus_cos = u.x * one_minus_cos_max;
    const Real cos_theta = 1 - one_minus_cos;
    // sin²θ = (1 − cos θ)(1 + cos θ): exact where 1 − cos² θ would cancel.
    const Real sin_theta = std::sqrt(std::max(Real(0), one_minus_cos * (2 - one_minus_cos)));
    return spherical(cos_theta, sin_theta, u.y);
    // END EXERCISE
}

Vec3 sample_power_cosine(Vec2 u, Real exponent) {
    // EXERCISE(ch04.power_cosine) § Four BRDFs
    // 1 − cos α = 1 − exp(ln(1 − u₁) / (e + 1)) through expm1 and log1p, so a sharp lobe (large e, cos α
    // within an ulp of 1) keeps sin α instead of rounding it to 0.
    const Real one_minus_cos = -std::expm1(std::log1p(-u.x) / (exponent + 1));
    const Real sin_alpha = std::sqrt(std::max(Real(0), one_minus_cos * (2 - one_minus_cos)));
    return spherical(1 - one_minus_cos, sin_alpha, u.y);
    // END EXERCISE
}

Vec2 sample_uniform_triangle(Vec2 u) {
    // EXERCISE(ch04.uniform_triangle) § Sampling the lights
    const Real s = std::sqrt(u.x);
    return {1 - s, u.y * s};
    // END EXERCISE
}

Real uniform_hemisphere_pdf(const Vec3& w) {
    // EXERCISE(ch04.uniform_hemisphere_pdf) § Four BRDFs
    return w.z >= 0 ? kUniformHemispherePdf : Real(0);
    // END EXERCISE
}

Real uniform_cone_pdf(const Vec3& w, Real one_minus_cos_max) {
    // EXERCISE(ch04.uniform_cone_pdf) § Sampling the lights
    if (!(one_minus_cos_max > 0)) return 0;
    // 1 − z from sin²θ / (1 + z) when z > 0, so a narrow cone keeps its digits.
    const Real sin2 = w.x * w.x + w.y * w.y;
    const Real one_minus_z = w.z > 0 ? sin2 / (1 + w.z) : 1 - w.z;
    return one_minus_z <= one_minus_cos_max ? Real(1) / (2 * kPi * one_minus_cos_max) : Real(0);
    // END EXERCISE
}

Real power_cosine_pdf(Real cos_alpha, Real exponent) {
    // EXERCISE(ch04.power_cosine_pdf) § Four BRDFs
    if (!(cos_alpha > 0)) return 0;
    return (exponent + 1) * Real(0.5) * kInvPi * std::pow(std::min(Real(1), cos_alpha), exponent);
    // END EXERCISE
}

}  // namespace rt
