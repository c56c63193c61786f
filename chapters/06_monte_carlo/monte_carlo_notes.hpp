// What chapter 06's summary says about a render: how materials are shaded, which strategies can see point
// lights, how the paths were sampled and ended, and the emitters not sampled as lights.
#pragma once

#include <string>
#include <vector>

#include "04_direct_lighting/render_scene.hpp"
#include "path_tracer.hpp"

namespace rt {

std::vector<std::string> monte_carlo_notes(const RenderScene& prepared, const PathOptions& options);

}  // namespace rt
