// What chapter 08's summary says about a render by each tracer: how materials are shaded, what a light path
// cannot show (delta surfaces seen through a pinhole, the environment, point lights), the emitters not
// sampled as lights, and what the tracer did and how its rays are counted.
#pragma once

#include <string>
#include <vector>

#include "04_direct_lighting/render_scene.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "combined_render.hpp"
#include "light_tracer.hpp"

namespace rt {

// `prepared` was built for importance, as the light tracer's was.
std::vector<std::string> forward_notes(const RenderScene& prepared, const LightTracerOptions& options,
                                       const SplatResult& result);
std::vector<std::string> reverse_notes(const Scene& scene, const EffectSet& simulated, Renderer renderer);
std::vector<std::string> combined_notes(const Scene& scene, const EffectSet& simulated,
                                        const CombinedOptions& options, const CombinedResult& result);

}  // namespace rt
