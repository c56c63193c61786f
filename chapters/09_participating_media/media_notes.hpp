// What chapter 09's summary says about a render: the renderer it chose, how the material table shades the
// scene's materials (media included), how the paths were sampled and their walks in media ended, and an
// environment that fog hides.
#pragma once

#include <string>
#include <vector>

#include "07_bsdf_refraction/bsdf_render.hpp"
#include "volume_path_tracer.hpp"

namespace rt {

// What an environment light behind fog gives: the top-level medium fills all space, so the environment lies
// infinitely deep in it and none of its light arrives in a channel where σ_t > 0 (e^(−σ_t·∞) = 0: the exact
// answer, not a fault). Empty unless the run simulates media and the scene has both.
std::string environment_behind_fog_note(const Scene& scene, const EffectSet& simulated);

std::vector<std::string> media_notes(const Scene& scene, Renderer renderer, const PathOptions& options,
                                     const MediumWalk& walk);

}  // namespace rt
