// An iterative path tracer. The recursion of chapter 05, L(x, wo) = Le + ∫ f L(x', −wi) cos θ dω, unrolled
// into a loop that carries the path throughput β = Π f cos θ / pdf:
//   L = Σ_k β_k (Le_k [+ next-event estimate at vertex k]),   β_{k+1} = β_k f(wo, wi) cos θ_i / pdf(wi),
// with the direction at each vertex drawn by the chosen SamplingStrategy, and chapter 05's Russian roulette
// (continue_path) ending it without bias: survive with probability q, then β /= q. A loop keeps no stack of
// frames, so a long path costs no memory, and the state the compiler keeps in registers is small.
#pragma once

#include <vector>

#include "brdf.hpp"
#include "camera.hpp"
#include "hit.hpp"
#include "light_picker.hpp"
#include "light_set.hpp"
#include "ray_offset.hpp"
#include "rt/random.hpp"
#include "rt/ray_counts.hpp"
#include "rt/render_loop.hpp"
#include "rt/scene.hpp"
#include "sampling_strategy.hpp"
#include "termination.hpp"
#include "world.hpp"

namespace rt {

struct PathOptions {
    SamplingStrategy strategy = SamplingStrategy::kMis;
    // Chapter 05's Russian roulette from bounce 3, under its safety cap of 64 bounces (a cap, not a bias).
    TerminationSettings termination{Termination::kRussianRoulette, kSafetyDepthCap};
    bool direct = true;    // effect "direct": light arriving from emitters at surfaces
    bool shadows = true;   // effect "shadows": shadow rays (false: every light sample counts as visible)
    bool indirect = true;  // effect "indirect": light after more than one diffuse or glossy bounce
    bool glossy = true;    // effect "glossy": false shades glossy and retro-reflective lobes as Lambert
    RayOffset offset{};
    Color dielectric_albedo{0.73f};  // dielectrics are shaded as Lambert of this albedo until chapter 07
};

class PathTracer {
  public:
    PathTracer(const World& world, const Scene& scene, const LightSet& lights, PathOptions options);

    // The radiance arriving along `ray` (a camera ray): one path, its estimate of L.
    Color radiance(const Ray& ray, Pcg32& rng, RayCounts& rays) const;

    const PathOptions& options() const { return options_; }
    const Brdf& brdf(int material) const { return brdfs_[std::size_t(material)]; }

  private:
    // The next-event estimate at `hit`: one area light sample (weighted for MIS), the environment (one
    // cosine-weighted direction) and every point light, each with its shadow ray.
    Color next_event(const Hit& hit, const Vec3& wo, const Brdf& brdf, Pcg32& rng, RayCounts& rays) const;
    // The BRDF-sampling density of wi that MIS weighs a light sample against.
    Real brdf_pdf(const Brdf& brdf, const Vec3& wo, const Vec3& wi, const Vec3& n) const;

    const World& world_;
    const Scene& scene_;
    LightPicker picker_;
    std::vector<PointLight> points_;
    std::optional<EnvironmentLight> environment_;
    PathOptions options_;
    std::vector<Brdf> brdfs_;                  // one per scene material
    std::vector<std::uint8_t> black_, delta_;  // per material: is_black, is_delta
    std::uint32_t bounded_primitives_ = 0;     // Hit::primitive at or above it: a plane
};

// Renders with `tracer`: one path per sample, through a stratified point of the pixel.
RenderResult render_paths(const PathTracer& tracer, const PinholeCamera& camera,
                          const RenderSettings& settings);

}  // namespace rt
