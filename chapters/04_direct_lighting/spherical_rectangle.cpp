#include "spherical_rectangle.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rt {
namespace {

// √(a² + b²): std::hypot guards against overflow at several times the cost, and the lengths here are scene
// distances, far from double's range.
double length2d(double a, double b) {
    return std::sqrt(a * a + b * b);
}

}  // namespace

std::optional<SphericalRectangle> SphericalRectangle::seen_from(const Vec3& p, const Vec3& corner,
                                                                const Vec3& U, const Vec3& V) {
    const double width = glm::length(Vec3d(U)), height = glm::length(Vec3d(V));
    if (!(width > 0) || !(height > 0)) return std::nullopt;
    const Vec3d x = Vec3d(U) / width, y = Vec3d(V) / height, z = glm::cross(x, y);
    const Vec3d d = Vec3d(corner) - Vec3d(p);
    SphericalRectangle r;
    r.z0_ = glm::dot(d, z);
    if (!(r.z0_ < 0)) return std::nullopt;  // in the plane, or behind the side z faces
    r.x0_ = glm::dot(d, x);
    r.y0_ = glm::dot(d, y);
    r.x1_ = r.x0_ + width;
    r.y1_ = r.y0_ + height;
    // The edges' normals in closed form (v00 × v10 = (x1 − x0) (0, z0, −y0), and so on), unit length.
    const double z0 = r.z0_;
    const Vec3d n0 = Vec3d(0, z0, -r.y0_) / length2d(z0, r.y0_);
    const Vec3d n1 = Vec3d(-z0, 0, r.x1_) / length2d(z0, r.x1_);
    const Vec3d n2 = Vec3d(0, -z0, r.y1_) / length2d(z0, r.y1_);
    const Vec3d n3 = Vec3d(z0, 0, -r.x0_) / length2d(z0, r.x0_);
    auto angle = [](const Vec3d& a, const Vec3d& b) {
        return std::acos(std::clamp(-glm::dot(a, b), -1.0, 1.0));
    };
    const double g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3), g3 = angle(n3, n0);
    constexpr double kTwoPi = 2 * std::numbers::pi;
    r.b0_ = n0.z;
    r.b1_ = n2.z;
    r.k_ = kTwoPi - g2 - g3;
    r.solid_angle_ = g0 + g1 - r.k_;  // = γ0 + γ1 + γ2 + γ3 − 2π
    return r;
}

Vec2 SphericalRectangle::sample(Vec2 u) const {
    // x: the part left of x has area A(x) = u Ω. With a = u Ω + k, the cosine between the x axis and the
    // direction (x, 0, z0) is c = sign(f) / √(f² + b0²), f = (cos a b0 − b1) / sin a;
    // then x = −c z0 / √(1 − c²).
    const double a = double(u.x) * solid_angle_ + k_;
    const double f = (std::cos(a) * b0_ - b1_) / std::sin(a);
    const double c = std::clamp(std::copysign(1.0, f) / length2d(f, b0_), -1.0, 1.0);
    double xu = -c * z0_ / std::sqrt(std::max(0.0, 1 - c * c));
    xu = std::isfinite(xu) ? std::clamp(xu, x0_, x1_) : (c > 0 ? x1_ : x0_);
    // y: along the line at xu (distance dist from p's axis), h = y / √(dist² + y²) is uniform in solid angle.
    const double dist = length2d(xu, z0_);
    const double h0 = y0_ / length2d(dist, y0_), h1 = y1_ / length2d(dist, y1_);
    const double h = h0 + double(u.y) * (h1 - h0);
    const double yv = h * h < 1 ? std::clamp(h * dist / std::sqrt(1 - h * h), y0_, y1_) : y1_;
    return Vec2(Real((xu - x0_) / (x1_ - x0_)), Real((yv - y0_) / (y1_ - y0_)));
}

}  // namespace rt
