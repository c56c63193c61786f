// Chapter 06's iterative path tracer with the smooth dielectric added. At each vertex the path throughput
// β = Π f cos θ / pdf is carried on, and
//   - a dielectric vertex chooses reflection (probability R) or transmission (T = 1 − R); β *= 1 or 1 / η²;
//     the choice is a delta, so light the path meets next counts in full (as after a mirror);
//   - any other vertex adds the next-event estimate β · L_direct (chapter 04's light sampling, with shadow
//     rays) and continues along a direction drawn from its BRDF; light the path then meets is not counted
//     again (it was in L_direct);
//   - inside absorbing glass, each segment of length d multiplies β by Beer–Lambert's exp(−σ_a d).
// Caustics (light → glass → diffuse surface → camera) come from paths that leave a diffuse surface, cross
// the glass and meet the lamp: a shadow ray cannot see the lamp through glass, so only these paths find them.
// Paths end by chapter 05's rules (continue_path): Russian roulette by default, a fixed depth for the study.
#pragma once

#include <optional>
#include <vector>

#include "camera.hpp"
#include "direct_lighting.hpp"
#include "ray_offset.hpp"
#include "rt/random.hpp"
#include "rt/ray_counts.hpp"
#include "rt/render_loop.hpp"
#include "rt/scene.hpp"
#include "termination.hpp"
#include "world.hpp"

namespace rt {

struct BsdfPathOptions {
    TerminationSettings termination{Termination::kRussianRoulette, kSafetyDepthCap};
    bool direct = true;    // effect "direct": next-event estimation at diffuse and glossy vertices
    bool shadows = true;   // effect "shadows"
    bool indirect = true;  // effect "indirect": a path goes on after its first diffuse or glossy vertex
    bool glossy = true;    // effect "glossy"
    // false: no light sampling; light a path meets counts at every vertex (chapter 06's "brdf" strategy, the
    // strategy without MIS the benchmark compares against).
    bool next_event = true;
    RayOffset offset{};
};

// Chapter 04's options for the same effects: its next-event estimate is this tracer's.
DirectOptions direct_options(const BsdfPathOptions& options);

class BsdfPathTracer {
  public:
    BsdfPathTracer(const World& world, const Scene& scene, const LightSet& lights, BsdfPathOptions options);

    // The radiance arriving along `ray` (a camera ray): one path's estimate.
    Color radiance(const Ray& ray, Pcg32& rng, RayCounts& rays) const;

  private:
    const World& world_;
    const Scene& scene_;
    DirectLighting direct_;  // chapter 04: the next-event estimate and the BRDF of every material
    BsdfPathOptions options_;
    std::optional<EnvironmentLight> environment_;
};

// One path per sample through a stratified point of the pixel.
RenderResult render_bsdf_paths(const BsdfPathTracer& tracer, const PinholeCamera& camera,
                               const RenderSettings& settings);

}  // namespace rt
