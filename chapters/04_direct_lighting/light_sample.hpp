// What sampling a light gives the shading point p: a point on the light, the direction toward it and the
// density of that direction in solid angle, so every light fits one estimator: f L cos θ / pdf.
#pragma once

#include "rt/core/math.hpp"

namespace rt {

struct LightSample {
    Vec3 point{0};      // on the light
    Vec3 wi{0, 0, 1};   // unit, from p toward `point`
    Real distance = 0;  // |point − p|
    Color radiance{0};  // L_e arriving at p along −wi
    Real pdf = 0;       // solid-angle density of wi (a point light: 1, a delta)
    // The light's surface at `point`: its unit normal and the rounding bound of `point` (chapter 03's
    // SurfacePoint), so the shadow ray stops before that surface at any distance from the origin. Zero for a
    // point light, which has no surface.
    Vec3 normal{0};
    Vec3 point_error{0};

    bool on_surface() const { return normal != Vec3(0); }
};

}  // namespace rt
