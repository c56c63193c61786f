// Numbers and vectors of the course: one alias for the precision of every renderer.
#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <numbers>

namespace rt {

// The precision of geometry and radiance: float, or double in a build configured with -DRT_DOUBLE=ON (the
// report builds both to compare them).
#ifdef RT_REAL_IS_DOUBLE
using Real = double;
#else
using Real = float;
#endif
using Vec2 = glm::vec<2, Real>;
using Vec3 = glm::vec<3, Real>;
using Vec2d = glm::dvec2;
using Vec3d = glm::dvec3;
// Linear RGB radiance (or reflectance) of one pixel or one path.
using Color = glm::vec<3, Real>;

inline constexpr Real kPi = std::numbers::pi_v<Real>;
inline constexpr Real kInvPi = std::numbers::inv_pi_v<Real>;
inline constexpr Real kInfinity = std::numeric_limits<Real>::infinity();
// The largest Real below 1: what a uniform random number in [0, 1) can be at most.
inline constexpr Real kOneMinusEpsilon = Real(1) - std::numeric_limits<Real>::epsilon() / 2;

inline Real radians(Real degrees) {
    return degrees * (kPi / Real(180));
}
inline Real luminance(const Color& c) {
    return Real(0.2126) * c.r + Real(0.7152) * c.g + Real(0.0722) * c.b;
}
// A colour with no positive channel reflects or emits nothing: no ray needs to be traced for it.
inline bool is_black(const Color& c) {
    return !(c.r > 0 || c.g > 0 || c.b > 0);
}
inline bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
// |v| per component, for rounding-error bounds. std::fabs clears the sign bit; glm::abs computes x >= 0 ? x : −x,
// which GCC compiles to a branch per component, mispredicted half the time on a path tracer's random vectors.
inline Vec3 abs(const Vec3& v) {
    return {std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)};
}

}  // namespace rt

namespace rt {

// True when a and b point along one line (or either is zero), judged in double: |a × b| ≤ 1e-12 |a| |b|.
// The camera cannot build its basis from a view direction and an up vector that are parallel.
inline bool parallel(const Vec3d& a, const Vec3d& b) {
    return glm::length(glm::cross(a, b)) <= 1e-12 * glm::length(a) * glm::length(b);
}

}  // namespace rt
