// Where a light path starts: a light chosen with probability P ∝ its power Φ (chapter 04's LightPicker, the
// one the path tracers sample for next-event estimation), a point on it and a direction it emits into. An
// area light of radiance Le and area A emits Φ = π lum(Le) A (one-sided, Lambertian; a two-sided one twice
// that, from a side picked with probability 1/2); a point light of intensity I emits Φ = 4π lum(I).
//   area light:  x uniform by area (pdf_A = 1 / A), ω cosine-weighted about its normal (pdf_ω = cos θ / π):
//                β₀ = Le cos θ / (P pdf_A pdf_ω) = π Le A / P;
//   point light: x is the point (a delta), ω uniform over the sphere (pdf_ω = 1 / 4π): β₀ = 4π I / P;
//   spot light:  x is the point, ω uniform in its cone: β₀ = I falloff(ω) 2π (1 − cos θ_end) / P;
//   distant:     x uniform on a disk of the scene's radius r facing the light (pdf_A = 1 / (π r²)), ω its
//                direction (a delta): β₀ = E π r² / P.
// β₀ is the light path's starting throughput: E[β₀ g(x, ω)] = ∫∫ Le cos θ g dA dω for any g, the power the
// path stands for. How each kind of light emits is this chapter's, found by the light's class
// (light_emission.cpp); a light of a class it does not know starts no light path (traced_forward).
#pragma once

#include <optional>
#include <string_view>

#include "02_intersection/hit.hpp"
#include "04_direct_lighting/light.hpp"
#include "04_direct_lighting/light_picker.hpp"
#include "04_direct_lighting/light_set.hpp"

namespace rt {

struct EmissionSample {
    Hit origin;                // the point on the light (point, point_error, normal on the emitting side)
    bool delta_light = false;  // a point, spot or distant light: no surface, no normal, no offset
    Color position_weight{0};  // Le / (P pdf_A) for an area light, I / P for a point or spot light
    Vec3 direction{0, 0, 1};   // unit, the emitted direction
    Color beta{0};             // β₀ = Le cos θ / (P pdf_A pdf_ω)
};

// Whether light paths start from `light` (its class has an emission sampler here).
bool traced_forward(const Light& light);

class EmitterSampler {
  public:
    // The lights of `lights` traced forward, in their order; the environment is not sampled.
    explicit EmitterSampler(const LightSet& lights);

    bool empty() const { return picker_.empty(); }
    std::size_t light_count() const { return picker_.light_count(); }
    // P(light i) = Φ_i / Σ Φ (the lights traced forward, in LightSet::lights' order).
    Real probability(std::size_t index) const { return picker_.probability(index); }
    // Σ Φ: π times the picker's weights, which leave the π out.
    Real total_power() const { return kPi * picker_.total_weight(); }

    // A light chosen by u_pick, a point on it from u_point, a direction from u_direction. Nothing when there
    // is no light.
    std::optional<EmissionSample> sample(Real u_pick, Vec2 u_point, Vec2 u_direction) const;

  private:
    LightPicker picker_;
};

}  // namespace rt
