#include "equal_area_map.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

Vec2 equal_area_point(const Vec3& w) {
    const Real z = std::clamp(w.z, Real(-1), Real(1));
    Real phi = std::atan2(w.y, w.x);
    if (phi < 0) phi += Real(2 * std::numbers::pi);
    // The pole z = 1, and φ just below 2π (which rounds to 1 in float): the square's point stays in [0, 1)².
    return {std::min((z + 1) / 2, kOneMinusEpsilon),
            std::min(phi / Real(2 * std::numbers::pi), kOneMinusEpsilon)};
}

Vec3 equal_area_direction(Vec2 p) {
    const Real z = 2 * p.x - 1;
    const Real r = std::sqrt(std::max(Real(0), 1 - z * z));
    const Real phi = Real(2 * std::numbers::pi) * p.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace rt
