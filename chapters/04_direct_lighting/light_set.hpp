// The lights of a scene, as chapter 04 samples them: every shape whose material has an emission is an area
// light (quads, box faces, triangles and mesh triangles sampled by area; spheres by solid angle), then the
// scene's own lights (points, distant lights, spots), each one Light (light.hpp); and the uniform
// environment, sampled apart.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "area_lights.hpp"
#include "light.hpp"
#include "rt/core/scene.hpp"

namespace rt {

struct LightSet {
    // In the order every sampler keeps: the area lights, quads then triangles then spheres, then the
    // scene's lights, points then distant lights then spots.
    std::vector<std::shared_ptr<const Light>> lights;
    std::optional<EnvironmentLight> environment;
    // Emitters that cannot be sampled (an infinite plane): they are seen by camera rays only.
    std::vector<std::string> unsampled;
    // By Hit::light: every emissive bounded primitive in scene order, numbered as chapter 02's World numbers
    // them, gives its place in `lights` (−1 for a degenerate emitter of zero area, which is left out).
    std::vector<int> by_hit;

    bool empty() const { return lights.empty() && !environment; }
};

// Every light of the scene. Degenerate emitters (zero area) are left out: they emit no power.
LightSet collect_lights(const Scene& scene);

}  // namespace rt
