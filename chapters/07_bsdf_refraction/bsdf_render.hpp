// Only the effects a scene calls for: chapter 07 renders with the cheapest renderer of the course that
// simulates needed(scene) ∩ supported:
//   direct: chapter 04's direct lighting (one camera ray, its shadow rays: maximum depth 1) when every
//           simulated effect is one chapter 04 has (camera, shadows, direct, glossy);
//   paths:  chapter 06's path tracer (MIS) when there is no refraction to simulate;
//   glass:  this chapter's path tracer with the dielectric BSDF otherwise.
// So a scene without glass pays nothing for refraction, and a direct-only scene nothing for paths.
#pragma once

#include <string_view>

#include "bsdf_path_tracer.hpp"
#include "rt/effect_set.hpp"
#include "rt/render_loop.hpp"
#include "rt/scene.hpp"

namespace rt {

enum class Renderer { kDirect, kPaths, kGlass };

// "direct (chapter 04)", "paths (chapter 06)" or "glass (chapter 07)".
std::string_view to_string(Renderer renderer);

inline constexpr EffectSet kDirectRendererEffects{Effect::kCameraRays, Effect::kShadows, Effect::kDirect,
                                                  Effect::kGlossy};

Renderer choose_renderer(const EffectSet& simulated);

// The options of a path tracer for the effects simulated: direct, shadows, indirect and glossy on or off.
BsdfPathOptions path_options_for(const EffectSet& simulated, BsdfPathOptions options = {});

// Renders `scene` with `renderer` (chapter 04's, 06's or this chapter's), the path tracers with `options`.
RenderResult render_with(Renderer renderer, const Scene& scene, const EffectSet& simulated,
                         const RenderSettings& settings, const BsdfPathOptions& options);

}  // namespace rt
