// Only the effects a scene calls for are simulated: needed(scene) ∩ supported(chapter).
#pragma once

#include <optional>
#include <string>

#include "rt/core/effect_set.hpp"
#include "rt/core/scene.hpp"

namespace rt {

// What the scene's content calls for (lights with anything they can light — a surface that reflects or
// transmits something, or a medium that scatters — → shadows, direct and indirect light; mirrors →
// reflection; glossy or retro-reflective materials → glossy; dielectrics → refraction, and reflection; a
// medium that scatters inside a dielectric, or any medium between the shapes → media; a mesh with vertex
// normals → shading normals), narrowed by the scene's "effects" list when it has one.
EffectSet needed(const Scene& scene);

// What a run of a chapter that supports `supported` simulates: needed(scene) ∩ supported. run_chapter()
// computes it so; the tests that check a render against an exact answer take it from here too.
EffectSet simulated_effects(const Scene& scene, const EffectSet& supported);

// The effect that shades material `m` as what it is rather than as a Lambert surface: reflection for a
// mirror, glossy for glossy and retro-reflective lobes, refraction for a dielectric; none for diffuse.
std::optional<Effect> effect_of(const Material& m);

// The course chapter that first simulates `effect` ("chapter 07"), for messages about skipped effects.
std::string chapter_that_adds(Effect effect);

}  // namespace rt
