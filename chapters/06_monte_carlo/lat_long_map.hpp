// The latitude–longitude map of an environment image: (u, v) in [0, 1)² ↔ a direction, with the map turned
// by an angle α about +y.
//   θ = π v (from +y, the image's top row, down to −y),  φ = 2π u (from +x toward +z),
//   local direction (sin θ cos φ, cos θ, sin θ sin φ),  world = R_y(α) · local.
// A cell du dv covers the solid angle dω = sin θ dθ dφ = 2π² sin θ du dv: the Jacobian that turns a density
// over the map into one over directions, p(ω) = p(u, v) / (2π² sin θ).
#pragma once

#include <algorithm>
#include <cmath>

#include "rt/core/math.hpp"

namespace rt {

struct LatLongMap {
    Real cos_alpha = 1, sin_alpha = 0;  // the turn about +y

    static LatLongMap turned_by_degrees(Real degrees) {
        const Real alpha = radians(degrees);
        return {std::cos(alpha), std::sin(alpha)};
    }

    Vec3 direction(Vec2 uv) const {
        const Real theta = kPi * uv.y, phi = 2 * kPi * uv.x;
        const Real sin_theta = std::sin(theta);
        const Vec3 local(sin_theta * std::cos(phi), std::cos(theta), sin_theta * std::sin(phi));
        // R_y(α), as a scene's rotate_y turns a shape (scene.cpp).
        return {cos_alpha * local.x + sin_alpha * local.z, local.y, -sin_alpha * local.x + cos_alpha * local.z};
    }

    // The point of the map seen along a unit `w`, and sin θ there. θ is taken as atan2(ρ, y) with
    // ρ = √(x² + z²) = sin θ itself: near the poles acos(y) loses every digit (a float y of 1 − 1e-9 is 1), and
    // sin(acos(y)) is then 0 for a direction that is not the pole.
    struct Point {
        Vec2 uv{0};
        Real sin_theta = 0;
    };
    Point point(const Vec3& w) const {
        const Real x = cos_alpha * w.x - sin_alpha * w.z, z = sin_alpha * w.x + cos_alpha * w.z;  // R_y(−α)
        const Real rho = std::sqrt(x * x + z * z);
        Real phi = std::atan2(z, x);
        if (phi < 0) phi += 2 * kPi;
        const Real u = std::min(phi * (Real(0.5) * kInvPi), kOneMinusEpsilon);
        const Real v = std::min(std::atan2(rho, w.y) * kInvPi, kOneMinusEpsilon);
        return {Vec2(u, v), rho};
    }
};

}  // namespace rt
