// What chapter 01 shows, before any surface exists: each ray's direction as a colour, over a sky gradient.
#pragma once

#include "rt/core/math.hpp"

namespace rt {

// A unit direction d as a colour: (d + 1) / 2, so +x is red, +y green, +z blue.
Color direction_colour(const Vec3& d);

// The sky: white straight down, blue (0.5, 0.7, 1.0) straight up, blended linearly in t = (d.y + 1) / 2.
Color sky_gradient(const Vec3& d);

}  // namespace rt
