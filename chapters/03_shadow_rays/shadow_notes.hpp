// What chapter 03's summary says about a render: the ray offset, the scene's scale, the shadow rays per
// camera ray, and what the chapter does not simulate in the scene (shading_notes).
#pragma once

#include <string>
#include <vector>

#include "ray_offset.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

std::vector<std::string> shadow_notes(const Scene& scene, const RayOffset& offset, Real scale,
                                      const RenderResult& result);

}  // namespace rt
