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
// mirror or a conductor (smooth or rough: all it does is reflect), glossy for glossy and retro-reflective
// lobes, refraction for a dielectric; none for diffuse.
std::optional<Effect> effect_of(const Material& m);

// The course chapter that first simulates `effect` ("chapter 07"), for messages about skipped effects.
std::string chapter_that_adds(Effect effect);

// Where material `m` is first shaded as what it is, for the notes of chapters that stand in for it:
// "reflection is simulated from chapter 05 on" (its effect and chapter_that_adds), except for a conductor,
// whose reflection is simulated from chapter 05 on but whose Fresnel and microfacets chapter 07 adds: "a
// conductor is simulated from chapter 07 on".
std::string simulated_from(const Material& m);

}  // namespace rt
