#include "warp_pdfs.hpp"

#include <algorithm>
#include <cmath>

#include "04_direct_lighting/sampling.hpp"

namespace rt {

Vec3 sample_uniform_sphere(Vec2 u) {
    // EXERCISE(ch06.uniform_sphere)
    const Real z = 1 - 2 * u.x;
    // sin²θ = (1 − z)(1 + z) = 4 u₁ (1 − u₁): no cancellation near the poles.
    const Real r = 2 * std::sqrt(std::max(Real(0), u.x * (1 - u.x)));
    const Real phi = 2 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
    // END EXERCISE
}

Real uniform_hemisphere_pdf(const Vec3& w) {
    // EXERCISE(ch06.uniform_hemisphere_pdf)
    return w.z >= 0 ? kUniformHemispherePdf : Real(0);
    // END EXERCISE
}

Real cosine_hemisphere_pdf(const Vec3& w) {
    // EXERCISE(ch06.cosine_hemisphere_pdf)
    return std::max(Real(0), w.z) * kInvPi;
    // END EXERCISE
}

Real uniform_cone_pdf(const Vec3& w, Real one_minus_cos_max) {
    // EXERCISE(ch06.uniform_cone_pdf)
    if (!(one_minus_cos_max > 0)) return 0;
    // 1 − z from sin²θ / (1 + z) when z > 0, so a narrow cone keeps its digits.
    const Real sin2 = w.x * w.x + w.y * w.y;
    const Real one_minus_z = w.z > 0 ? sin2 / (1 + w.z) : 1 - w.z;
    return one_minus_z <= one_minus_cos_max ? Real(1) / (2 * kPi * one_minus_cos_max) : Real(0);
    // END EXERCISE
}

Real power_cosine_pdf(const Vec3& w, Real exponent) {
    // EXERCISE(ch06.power_cosine_pdf)
    if (!(w.z >= 0)) return 0;
    return (exponent + 1) * Real(0.5) * kInvPi * std::pow(std::min(Real(1), w.z), exponent);
    // END EXERCISE
}

Vec3 sample_quad_point(const Vec3& origin, const Vec3& u_edge, const Vec3& v_edge, Vec2 u) {
    return origin + u.x * u_edge + u.y * v_edge;
}

Vec3 sample_triangle_point(const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec2 u) {
    const Vec2 b = sample_uniform_triangle(u);
    return (1 - b.x - b.y) * p0 + b.x * p1 + b.y * p2;
}

}  // namespace rt
