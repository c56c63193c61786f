// What a chapter 05 run says in its summary besides the image: the materials the table shades by a stand-in,
// the lobes this chapter samples only uniformly, the termination rule and its bias, the lights and the
// emitters light sampling misses, the rays per camera ray, and a furnace's exact answer.
#pragma once

#include <string>
#include <vector>

#include "04_direct_lighting/direct_lighting.hpp"
#include "furnace.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"
#include "termination.hpp"

namespace rt {

std::vector<std::string> gi_notes(const Scene& scene, const DirectLighting& shading,
                                  const TerminationSettings& termination, const RenderResult& result);

// "furnace: exact L = Le / (1 - rho) = …", with the rule's expected value when it cuts paths at a depth.
std::string furnace_note(const Furnace& furnace, const TerminationSettings& termination, bool indirect);

}  // namespace rt
