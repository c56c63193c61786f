#include "direction_shading.hpp"

#include <algorithm>

namespace rt {

Color direction_colour(const Vec3& d) { return (d + Real(1)) * Real(0.5); }

Color sky_gradient(const Vec3& d) {
    const Real t = std::clamp((d.y + Real(1)) / Real(2), Real(0), Real(1));
    return (Real(1) - t) * Color(1) + t * Color(0.5f, 0.7f, 1.0f);
}

}  // namespace rt
