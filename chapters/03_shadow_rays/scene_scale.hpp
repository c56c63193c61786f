// The same scene at another size: every length multiplied by s (about the origin), so its coordinates reach
// s times as far, and every point light's intensity by s², so that E = I cos θ / r² — and the picture — stay
// the same. Only the floating-point numbers change: what an offset does at 1e-3 and at 1e5 can be compared.
#pragma once

#include "rt/scene.hpp"

namespace rt {

// Throws InputError unless s is in [1e-12, 1e12] (intensities × s² stay finite in float).
Scene scale_scene(const Scene& scene, Real s);

}  // namespace rt
