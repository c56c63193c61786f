// A ray: the points origin + t·direction for t in [0, ∞).
#pragma once

#include "rt/core/math.hpp"

namespace rt {

struct Ray {
    Vec3 origin{0};
    Vec3 direction{0, 0, 1};

    Vec3 at(Real t) const { return origin + t * direction; }
};

}  // namespace rt
