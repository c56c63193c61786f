// The direct term of the rendering equation at a surface point p seen from direction wo:
//   L_o(p, wo) = L_e(p, wo) + ∫ f(wo, wi) L_e(x(wi), −wi) V(p, x) cos θ_i dω_i
// where x(wi) is the light seen along wi and V its visibility. Estimated light by light: N directions wi_j
// drawn from each light's own density pdf(wi) (area lights), one for a point light (a delta: L_e dω becomes
// I / d²), N cosine-weighted ones for the environment:
//   L_direct ≈ Σ_lights (1 / N) Σ_j f(wo, wi_j) L_e(wi_j) cos θ_j V_j / pdf(wi_j).
// A shadow ray is traced only when its sample could carry light (f, L_e and cos θ all > 0).
#pragma once

#include <optional>

#include "02_intersection/hit.hpp"
#include "02_intersection/world.hpp"
#include "bsdf.hpp"
#include "light_picker.hpp"
#include "light_sample.hpp"
#include "light_set.hpp"
#include "material_table.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/core/random.hpp"
#include "rt/core/ray_counts.hpp"
#include "trace_options.hpp"

namespace rt {

// How the N samples of one light are spread over the unit square they are warped from: independently, or one
// in each cell of an m × m grid (m = ⌊√N⌋; the rest independent), which evens out where the samples land.
enum class LightSampler { kIndependent, kStratified };

constexpr auto names_of(LightSampler) {
    return enum_names<LightSampler>(
        "--light-sampler", {{LightSampler::kIndependent, "independent"}, {LightSampler::kStratified, "stratified"}});
}

// Which lights a hit samples. Every light, N samples each, is this chapter's estimator; its cost grows with
// the number of lights (50 000 emissive spheres: 50 000 N shadow rays per hit). Picking N lights with
// probability proportional to their power (the LightPicker, pdf = P(light) pdf_light) costs N shadow rays
// whatever their number, at the price of more noise when few lights matter at a point. kAuto samples every
// light up to kEveryLightLimit lights, and picks beyond.
enum class LightSelection { kAuto, kEvery, kPower };
inline constexpr std::size_t kEveryLightLimit = 16;

constexpr auto names_of(LightSelection) {
    return enum_names<LightSelection>(
        "--light-selection",
        {{LightSelection::kAuto, "auto"}, {LightSelection::kEvery, "every"}, {LightSelection::kPower, "power"}});
}

// Effects read: "direct" (sample the lights at all), "shadows" (trace shadow rays; without it every light
// counts as visible). The material table holds what "glossy" changes.
struct DirectOptions : TraceOptions {
    int shadow_samples = 1;  // N: shadow rays per light (or picked lights) and for the environment per hit
    LightSampler light_sampler = LightSampler::kStratified;
    LightSelection light_selection = LightSelection::kAuto;
};

// What shading needs, built once per render.
class DirectLighting {
  public:
    // `world` and `materials` must outlive it.
    DirectLighting(const World& world, const MaterialTable& materials, LightSet lights,
                   DirectOptions options);

    // The direct term at `hit` toward wo (unit, pointing away from the surface, on the side of hit.normal).
    Color direct(const Hit& hit, const Vec3& wo, Pcg32& rng, RayCounts& rays) const;
    // The radiance arriving along a camera ray: emission and direct light at the nearest hit, or the
    // environment when the ray leaves the scene.
    Color radiance(const Ray& ray, Pcg32& rng, RayCounts& rays) const;

    const MaterialTable& materials() const { return materials_; }
    const LightSet& lights() const { return lights_; }
    // Whether hits pick their lights by power (LightSelection, resolved for this scene's lights).
    bool picks_lights() const { return picker_.has_value(); }
    const DirectOptions& options() const { return options_; }
    const World& world() const { return world_; }

  private:
    // The point of [0, 1)² that light sample j of N is warped from.
    Vec2 light_point(int j, Pcg32& rng) const;
    // Σ over every light of (1 / N) Σ_j f L cos / pdf (a delta light: its one sample), with their shadow
    // rays.
    Color every_light(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, Pcg32& rng, RayCounts& rays) const;
    // (1 / N) Σ_j f L cos / pdf over N lights picked by power.
    Color picked_lights(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, Pcg32& rng, RayCounts& rays) const;
    // Adds the environment's N cosine-weighted samples to `sum`.
    void add_environment(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, Pcg32& rng, RayCounts& rays,
                         Color& sum) const;
    // One light sample's contribution f L cos / pdf, with its shadow ray; 0 without tracing when it is 0.
    Color contribution(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, const LightSample& sample,
                       RayCounts& rays) const;

    const World& world_;
    const MaterialTable& materials_;
    LightSet lights_;
    DirectOptions options_;
    std::optional<LightPicker> picker_;  // with LightSelection::kPower (or kAuto beyond the limit)
};

}  // namespace rt
