// The five ways this chapter samples the integral L = Le + ∫ f L cos θ dω at each path vertex:
//   uniform: wi uniform over the hemisphere (pdf 1 / 2π), light only where a path happens to hit it;
//   cosine:  wi cosine-weighted (pdf cos θ / π): cancels the cos θ of the integrand;
//   brdf:    wi drawn from the BRDF's own sampler (pdf ∝ f cos θ for Lambert, the lobe for glossy);
//   light:   next-event estimation: a point on a light and a shadow ray at every vertex, plus a BRDF
//            sample to continue the path (which then no longer counts the light it hits);
//   mis:     both the light sample and the BRDF sample count, weighted by the power heuristic.
#pragma once

#include <array>

#include "rt/core/enum_names.hpp"

namespace rt {

enum class SamplingStrategy { kUniform, kCosine, kBrdf, kLight, kMis };

inline constexpr std::array<SamplingStrategy, 5> kAllStrategies = {
    SamplingStrategy::kUniform, SamplingStrategy::kCosine, SamplingStrategy::kBrdf, SamplingStrategy::kLight,
    SamplingStrategy::kMis};

constexpr auto names_of(SamplingStrategy) {
    return enum_names<SamplingStrategy>("--sampling", {{SamplingStrategy::kUniform, "uniform"},
                                                       {SamplingStrategy::kCosine, "cosine"},
                                                       {SamplingStrategy::kBrdf, "brdf"},
                                                       {SamplingStrategy::kLight, "light"},
                                                       {SamplingStrategy::kMis, "mis"}});
}
// Whether the strategy samples the lights directly (next-event estimation): light and mis.
inline bool samples_lights(SamplingStrategy s) {
    return s == SamplingStrategy::kLight || s == SamplingStrategy::kMis;
}

}  // namespace rt
