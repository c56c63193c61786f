// Only the effects a scene calls for: chapter 07 renders with the cheapest renderer of the course that
// simulates needed(scene) ∩ supported:
//   direct: chapter 04's direct lighting (one camera ray, its shadow rays: maximum depth 1) when every
//           simulated effect is one chapter 04 has (camera, shadows, direct, glossy);
//   paths:  chapter 06's path loop otherwise, with MIS, on a material table that holds this chapter's
//           dielectrics when refraction is simulated (refraction_materials.hpp).
// So a direct-only scene pays nothing for paths, and a scene without glass only one flag test per vertex for
// the transmission it does not have.
#pragma once

#include <string_view>

#include "06_monte_carlo/path_tracer.hpp"
#include "refraction_materials.hpp"
#include "rt/core/effect_set.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

// What this chapter simulates (its ChapterInfo::supported; chapter 08 the same): all but media.
inline constexpr EffectSet kRefractionChapterEffects = EffectSet::all().without({Effect::kMedia});

enum class Renderer { kDirect, kPaths };

// Its names, for the notes (no flag takes them: the effects choose the renderer).
constexpr auto names_of(Renderer) {
    return enum_names<Renderer>("renderer",
                                {{Renderer::kDirect, "direct (chapter 04)"},
                                 {Renderer::kPaths, "paths (chapter 06's loop, chapter 07's BSDFs)"}});
}

inline constexpr EffectSet kDirectRendererEffects{Effect::kCameraRays, Effect::kShadows, Effect::kDirect,
                                                  Effect::kGlossy};

Renderer choose_renderer(const EffectSet& simulated);

// Renders `scene` with `renderer`, the path loop with `options` (its effects set to `simulated`), on the
// material table `hooks` make (this chapter's dielectrics; chapter 09 hands in its media too).
RenderResult render_with(Renderer renderer, const Scene& scene, const EffectSet& simulated,
                         const RenderSettings& settings, PathOptions options = {},
                         const MaterialHooks& hooks = refraction_materials());

}  // namespace rt
