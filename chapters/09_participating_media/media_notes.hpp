// What chapter 09's summary says about a render: the renderer it chose, how the material table shades the
// scene's materials (media included), and how the paths were sampled and their walks in media ended.
#pragma once

#include <string>
#include <vector>

#include "07_bsdf_refraction/bsdf_render.hpp"
#include "volume_path_tracer.hpp"

namespace rt {

std::vector<std::string> media_notes(const Scene& scene, Renderer renderer, const PathOptions& options,
                                     const MediumWalk& walk);

}  // namespace rt
