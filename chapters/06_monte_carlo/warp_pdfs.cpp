#include "warp_pdfs.hpp"

#include <algorithm>
#include <cmath>

#include "04_direct_lighting/sampling.hpp"

namespace rt {

Vec3 sample_uniform_sphere(Vec2 u) {
    // EXERCISE(ch06.uniform_sphere) § Sampling routines and their densities
    const Real z = 1 - 2 * u.x;
    // sin²θ = (1 − z)(1 + z) = 4 u₁ (1 − u₁): no cancellation near the poles.
    const Real r = 2 * std::sqrt(std::max(Real(0), u.x * (1 - u.x)));
    const Real phi = 2 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
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
