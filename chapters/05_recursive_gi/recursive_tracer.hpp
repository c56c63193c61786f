// The rendering equation as a recursion. The radiance leaving x toward wo is what x emits plus what it
// reflects of the radiance arriving from every direction, which is itself the radiance leaving another point:
//   L(x, wo) = Le(x, wo) + ∫ f(x, wo, wi) L(x'(wi), −wi) cos θ_i dω_i
// One trace() call estimates it for one ray, with one path vertex per call:
//   L ≈ Le                         counted where no other term already holds it (below)
//     + L_direct(x, wo)            chapter 04's light sampling (diffuse, glossy; 0 for a mirror)
//     + w · L(x', −wi)             one continuation ray: the mirror direction (w = R, a reflection ray), or
//                                  one uniform hemisphere direction (w = f cos θ_i · 2π, an indirect ray)
// The continuation carries the throughput β (the product of the weights w from the camera on), which the
// termination rule reads to stop the path; each call returns β · L.
// Emission is counted once. Light sampling already holds the light that travels straight from a sampled
// emitter to x, so an indirect ray that hits that emitter must not add it again: Le is counted on camera
// rays, after mirror bounces (a light sample never hits a delta BRDF), and on indirect rays only for emitters
// light sampling cannot reach (an emissive plane; every emitter when the effect "direct" is off).
#pragma once

#include <vector>

#include "04_direct_lighting/direct_lighting.hpp"
#include "rt/core/random.hpp"
#include "rt/core/ray.hpp"
#include "rt/core/ray_counts.hpp"
#include "termination.hpp"

namespace rt {

// The effects come with the shading (DirectLighting's options): "indirect" gives one indirect ray per
// diffuse or glossy bounce; without "reflection" the material table has made mirrors black.
struct GiOptions {
    TerminationSettings termination{};
};

class RecursiveTracer {
  public:
    // `shading` supplies the world, the lights, the material table and the direct term; it must outlive the
    // tracer.
    RecursiveTracer(const DirectLighting& shading, GiOptions options);

    // The radiance arriving along a camera ray: trace(ray, kCamera, 0, β = 1).
    Color radiance(const Ray& ray, Pcg32& rng, RayCounts& rays) const;

    // β · L(ray) for a ray of kind `kind` (camera, reflection or indirect) that arrives at the path's vertex
    // number `depth` (the bounces made before it; 0 for the camera ray's hit).
    Color trace(const Ray& ray, RayKind kind, int depth, Color throughput, Pcg32& rng, RayCounts& rays) const;

    // Whether light sampling holds the emission seen at `hit` (and an indirect ray must not count it again).
    bool emission_sampled_by_direct(const Hit& hit) const;

    const GiOptions& options() const { return options_; }
    const DirectLighting& shading() const { return shading_; }

  private:
    const DirectLighting& shading_;
    GiOptions options_;
    bool indirect_;  // the effect "indirect" is simulated
    // True when an indirect ray can find light light sampling has not counted (unsampled emitters, or no
    // light sampling at all); otherwise the last indirect ray under a depth cap would add nothing.
    bool indirect_rays_find_emitters_;
};

}  // namespace rt
