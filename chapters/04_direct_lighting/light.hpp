// What every light answers, so that next-event estimation, the picker and MIS treat all kinds alike:
//   sample        a direction toward the light from a point p, with its solid-angle density (a delta light:
//                 its one direction, pdf 1 by convention, and L_e / pdf = what arrives);
//   pdf           the density with which the picker draws a direction that met the light (MIS weighs a BSDF
//                 sample that hit the light with it);
//   power_weight  Φ / π, what the picker chooses lights in proportion to;
//   is_delta      whether no ray can meet the light (a point, a spot, a distant light): its light arrives
//                 by sampling alone, and one sample finds it all.
// The emission a ray meets is its material's (MaterialTable::emission): a light does not say it twice.
// Each kind is one class in one file (quad_emitter.hpp, ..., spot_emitter.hpp); light_set.cpp makes them from
// the scene. Later chapters add what they need by the light's class: chapter 08 where light paths start
// (light_emission.cpp), chapter 11 the record the shaders read (gpu_scene.cpp).
#pragma once

#include <optional>
#include <string_view>

#include "02_intersection/hit.hpp"
#include "light_sample.hpp"
#include "quad_light_strategy.hpp"

namespace rt {

// What the picker knows when it asks one of its lights for a density.
struct PickedLight {
    Real probability = 1;   // P(light) = Φ / Σ Φ
    Real total_weight = 0;  // W = Σ Φ / π over the picker's lights
    QuadLightSampling quads = QuadLightSampling::kArea;
};

class Light {
  public:
    virtual ~Light() = default;

    // A direction toward the light from p, drawn from u; `quads` says how a quad light samples (the other
    // kinds have one way). Nothing when p cannot be lit by it (behind a one-sided light, outside a spot's
    // cone).
    virtual std::optional<LightSample> sample(const Vec3& p, Vec2 u, QuadLightSampling quads) const = 0;
    // P(light) × the density with which sample() draws wi from p, when the ray p + t wi first meets this
    // light at `hit` (on its emitting side). 0 for a delta light, which no ray meets.
    virtual Real pdf(const Vec3& p, const Vec3& wi, const Hit& hit, const PickedLight& picked) const = 0;
    // Φ / π: the power the light emits in all, without the common factor π.
    virtual Real power_weight() const = 0;
    virtual bool is_delta() const = 0;
    // "quad", "point", ...: what notes count lights by.
    virtual std::string_view kind() const = 0;
};

}  // namespace rt
