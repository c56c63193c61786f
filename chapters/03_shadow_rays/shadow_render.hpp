// Chapter 03's picture: what the camera sees, lit by the scene's point lights through shadow rays.
//   L(p) = L_e(p) + Σ_lights k ρ E_i V_i,   k ρ E_i = lambert_radiance,   V_i = 1 if the light is visible
// A shadow ray is traced only where it can change the answer: a light behind the surface (cos θ ≤ 0) adds
// nothing and costs nothing, and a scene without point lights traces no shadow rays at all.
#pragma once

#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "ray_offset.hpp"
#include "rt/core/effect_set.hpp"
#include "rt/core/random.hpp"
#include "rt/core/ray_counts.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

// What this chapter simulates (its ChapterInfo::supported).
inline constexpr EffectSet kShadowChapterEffects{Effect::kCameraRays, Effect::kShadows, Effect::kDirect};

struct ShadowOptions {
    RayOffset offset{};
    bool direct = true;   // effect "direct": light the surfaces at all
    bool shadows = true;  // effect "shadows": trace shadow rays (false: every light counts as visible)
};

// The options of a run that simulates `simulated` and leaves surfaces by `offset`.
ShadowOptions shadow_options(const EffectSet& simulated, const RayOffset& offset);

// The ray of sample `s` (stratified in its pixel, `spp` samples per pixel) from the camera.
Ray primary_ray(const PinholeCamera& camera, const PixelSample& s, int spp, Pcg32& rng);

// The direct light of the scene's point lights at `hit`, a surface of that albedo: Σ k ρ E_i V_i, one
// shadow ray per light in front.
Color point_lights_at(const World& world, const Scene& scene, const Hit& hit, const Color& albedo,
                      const ShadowOptions& options, RayCounts& rays);

// Each material's albedo as this chapter shades it (its stand-in Lambert), by material index: found once,
// not at every hit.
std::vector<Color> stand_in_albedos(const Scene& scene);

// The radiance along a camera ray: at the nearest hit, emission plus the point lights' direct light; on a
// miss, the environment's radiance (black without one).
Color radiance(const World& world, const Scene& scene, const std::vector<Color>& albedos, const Ray& ray,
               const ShadowOptions& options, RayCounts& rays);

RenderResult render_shadows(const World& world, const Scene& scene, const PinholeCamera& camera,
                            const ShadowOptions& options, const RenderSettings& settings);

// What this chapter does not simulate in `scene`, one line each: lights other than point lights, and
// materials shaded as Lambertian or textures shaded as their mean colour, with the chapter that adds them.
std::vector<std::string> shading_notes(const Scene& scene);

}  // namespace rt
