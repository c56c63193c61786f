// What chapter 07's summary says about a render: the renderer it chose, how the material table shades the
// scene's materials, and how the paths were sampled and ended.
#pragma once

#include <string>
#include <vector>

#include "06_monte_carlo/path_tracer.hpp"
#include "bsdf_render.hpp"
#include "rt/core/scene.hpp"

namespace rt {

std::vector<std::string> refraction_notes(const Scene& scene, Renderer renderer, const PathOptions& options);

}  // namespace rt
