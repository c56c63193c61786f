// What chapter 02's summary says about a render: what the pixels show, the world and its BVH, what a camera
// ray cost, and whether each closed mesh leaks rays from inside.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "intersection_render.hpp"
#include "rt/core/scene.hpp"
#include "world.hpp"

namespace rt {

struct IntersectionRun {
    ShowMode show;
    WorldOptions options;
    double build_seconds;  // building the world and its BVH
    int threads;
};

// The notes of a render; `cost` (none once the render was interrupted) also decides whether the leak probe
// runs on each mesh of the scene.
std::vector<std::string> intersection_notes(const Scene& scene, const World& world,
                                            const IntersectionRun& run, const RenderResult& result,
                                            const std::optional<MeanTraversalCost>& cost);

}  // namespace rt
