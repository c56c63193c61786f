// What sampling a light gives the shading point p: a point on the light, the direction toward it and the
// density of that direction in solid angle, so every light fits one estimator: f L cos θ / pdf.
#pragma once

#include "rt/math.hpp"

namespace rt {

struct LightSample {
    Vec3 point{0};      // on the light
    Vec3 wi{0, 0, 1};   // unit, from p toward `point`
    Real distance = 0;  // |point − p|
    Color radiance{0};  // L_e arriving at p along −wi
    Real pdf = 0;       // solid-angle density of wi (a point light: 1, a delta)
};

}  // namespace rt
