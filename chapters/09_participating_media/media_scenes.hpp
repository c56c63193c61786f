// The small scenes chapter 09's studies and tests are built on, as plain Scene data: a sphere of a medium
// under a uniform sky (the white furnace when its albedo is 1), and a wide slab of a medium seen straight on.
#pragma once

#include "rt/core/scene.hpp"

namespace rt {

// A sphere of radius 1 at the origin, a dielectric of index `ior` holding `medium`, under a uniform sky of
// radiance `sky`; the camera 4 units away on +z looks at its centre.
Scene medium_sphere_scene(const MediumDesc& medium, Real ior = 1, Real sky = 1);

// A slab 0 ≤ y ≤ thickness (index-matched, 2·10⁴ wide: infinite for light that travels less than 10⁴ in it),
// holding `medium`, over a black floor at y = −2, under a uniform sky of radiance 1. Seen straight down from
// above, it shows what it reflects (what passes through is lost in the floor); straight up from between it
// and the floor, the sky through it and what it transmits.
Scene medium_slab_scene(const MediumDesc& medium, Real thickness);

}  // namespace rt
