// What chapter 09 adds to the material table: chapter 07's dielectrics, and with media simulated the medium a
// scene's "medium" describes — inside a dielectric's shapes or between the shapes — as a HomogeneousMedium
// when it scatters (chapter 07's Beer–Lambert AbsorbingMedium when it only absorbs, nothing when it is
// empty).
#pragma once

#include "04_direct_lighting/material_table.hpp"

namespace rt {

// What chapter 09 simulates (its ChapterInfo::supported; chapter 10's too): every effect.
inline constexpr EffectSet kMediaChapterEffects = EffectSet::all();

MaterialHooks media_materials();

// Whether `bsdf` is a boundary between media that a path and its shadow rays cross straight on: chapter 07's
// smooth glass of η = 1 (ior 1), which neither bends nor reflects light (an index-matched boundary).
bool index_matched(const Bsdf& bsdf);

}  // namespace rt
