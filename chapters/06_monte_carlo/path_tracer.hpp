// An iterative path tracer: the course's one path loop. The recursion of chapter 05,
// L(x, wo) = Le + ∫ f L(x', −wi) |cos θ| dω, unrolled into a loop that carries the path throughput
// β = Π f |cos θ| / pdf:
//   L = Σ_k β_k (Le_k [+ next-event estimate at vertex k]),   β_{k+1} = β_k f(wo, wi) |cos θ_i| / pdf(wi),
// with the direction at each vertex drawn by the chosen SamplingStrategy, and chapter 05's Russian roulette
// (continue_path) ending it without bias: survive with probability q, then β /= q. A loop keeps no stack of
// frames, so a long path costs no memory, and the state the compiler keeps in registers is small.
// It reads every material through the Bsdf interface and the material table, so later chapters extend it
// without a fork: a BSDF with transmission sends the path through the surface (chapter 07's glass), a delta
// BSDF is followed like a mirror (what it meets next counts in full), and a segment that ends on the inside
// of a shape whose material has a Medium is attenuated by its transmittance (chapter 07's Beer–Lambert).
// A medium that scatters (chapter 09, through the Medium interface of chapter 04's medium.hpp) makes the loop
// volumetric: along each segment the medium samples a free flight, and where it scatters the loop makes a
// vertex in the volume, with the phase function in the place of the BSDF (next-event estimation whose shadow
// rays carry transmittance through media and index-matched boundaries, MIS of phase and light sampling, a
// direction drawn from the phase function). A scene without media draws the random numbers it always drew.
#pragma once

#include "01_ray_generation/camera.hpp"
#include "02_intersection/hit.hpp"
#include "02_intersection/world.hpp"
#include "04_direct_lighting/bsdf.hpp"
#include "04_direct_lighting/light_picker.hpp"
#include "04_direct_lighting/light_set.hpp"
#include "04_direct_lighting/material_table.hpp"
#include "04_direct_lighting/trace_options.hpp"
#include "05_recursive_gi/termination.hpp"
#include "path_parts.hpp"
#include "rt/random.hpp"
#include "rt/ray_counts.hpp"
#include "rt/render_loop.hpp"
#include "sample_stream.hpp"
#include "sampling_strategy.hpp"

namespace rt {

// How a path that scatters in a medium (chapter 09) ends. Its scattering events are not the bounces that
// `termination` counts (a walk in milk makes hundreds of them): they have their own two knobs.
struct MediumWalk {
    int max_events = 10000;  // a hard cap on a path's events in media (scattering, and reflections at a
                             // walk's boundary): a bias when a path meets it
    bool roulette = true;  // Russian roulette at every event: go on with q = min(1, max β), then β /= q
};

// Effects read: "direct" (light arriving from emitters at surfaces), "shadows" (shadow rays; without it every
// light sample counts as visible), "indirect" (light after more than one diffuse or glossy bounce). The
// material table holds what "glossy", "reflection" and "refraction" change.
struct PathOptions : TraceOptions {
    SamplingStrategy strategy = SamplingStrategy::kMis;
    // Chapter 05's Russian roulette from bounce 3, under its safety cap of 64 bounces (a cap, not a bias).
    TerminationSettings termination{Termination::kRussianRoulette, kSafetyDepthCap};
    // Russian roulette judges β with refraction's radiance scaling (1/η² into glass, ×η² out) divided out,
    // PBRT's η-scale: otherwise a path inside glass survives with 1/η² of its chance and comes out η² times
    // brighter, the fireflies of the glass box's caustics (chapter 06's error study). false: judges β itself.
    bool roulette_eta_scale = true;
    // K > 0 leaves out every path that begins, from the camera, with 1 to K non-delta vertices and then a
    // delta one (glass, a mirror): E D{1..K} S …, the caustics the camera sees with no glass or mirror in
    // between. The loop finds the bright ones only when BSDF samples happen to pass the glass and hit the
    // light (its fireflies: light sampling cannot see a lamp through glass). Chapter 08's light tracer finds
    // them from the light's side (LightPathSet::kCaustics with the same K), and the two images add up to the
    // whole: every path is counted by exactly one of them. The path ends at that delta vertex (what follows is
    // the light tracer's). Only for scenes without media, whose lights are all sampled. 0: every path.
    int camera_caustic_bounces = 0;
    // Where a sample's numbers come from (sample_stream.hpp; render_paths reads it).
    PointSet sampler = PointSet::kStratified;
    MediumWalk walk;
};

// What the camera ray's path meets at its first vertex that is not a delta bounce, having followed mirrors
// and glass the way it goes on: chapter 10's feature buffers (a denoiser's guides). Left as it is (zeros, not
// recorded) by a path that leaves the scene first.
struct PathFeatures {
    Color albedo{0};  // the bounce's weight there, f |cos θ_i| / pdf, times the delta chain's β before it:
                      // an estimate of the surface's albedo ρ(wo) as seen through the chain (0 on a light)
    Vec3 normal{0};   // the shading normal there, on the side the path came from
    Real depth = 0;   // the path's length from the camera to there, through the chain
    bool recorded = false;
};

class PathTracer {
  public:
    // `world` and `materials` must outlive it.
    PathTracer(const World& world, const MaterialTable& materials, const LightSet& lights,
               PathOptions options);

    // The radiance arriving along `ray` (a camera ray): one path, its estimate of L. Given `features`, it
    // records them there too (the path and its random numbers are the same with or without); given `parts`,
    // it adds each term of L there by the kind of path it came from (path_parts.hpp, an analysis hook).
    Color radiance(const Ray& ray, SampleStream rng, RayCounts& rays, PathFeatures* features = nullptr,
                   PathParts* parts = nullptr) const;

    const PathOptions& options() const { return options_; }
    const MaterialTable& materials() const { return materials_; }
    const LightPicker& lights() const { return picker_; }

  private:
    // The next-event estimate at `hit`: one light picked by power (an area light weighted for MIS; a point
    // light is a delta, weight 1) and the environment (one cosine-weighted direction), each with its shadow
    // ray.
    Color next_event(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, SampleStream rng,
                     RayCounts& rays) const;

    // Chapter 09's media. The medium a segment runs through, judged at its end: the inside of a shape when
    // it ends on the back of a surface that lets light through, the medium between the shapes otherwise.
    const Medium* medium_along(const std::optional<Hit>& end) const;
    // The transmittance from ray.origin to ray.at(t_max) (a shadow ray): through media, across
    // index-matched boundaries, 0 at any other surface. Counts a shadow ray per segment.
    Color transmittance(Ray ray, Real t_max, RayCounts& rays) const;
    // What a light sample from `hit` sees of `target`: 0 or 1 (chapter 03's visibility) in a scene without
    // media, the transmittance with them.
    Color seen(const Hit& hit, const Vec3& target, RayCounts& rays) const;
    // The next-event estimate at a scattering event at p in a medium: as next_event, with the phase function
    // for the BSDF, no cosine, and the environment sampled over the whole sphere.
    Color next_event_in_medium(const Vec3& p, const Vec3& wo, const PhaseFunction& phase, SampleStream rng,
                               RayCounts& rays) const;

    const World& world_;
    const MaterialTable& materials_;
    LightPicker picker_;
    std::optional<EnvironmentLight> environment_;
    bool has_unsampled_emitters_;  // an emissive plane: only paths that hit it see it
    const Medium* exterior_;       // the medium between the shapes (null: empty space)
    bool media_;                   // a medium between the shapes, or one that scatters inside a shape
    PathOptions options_;
};

// Renders with `tracer`: one path per sample, its numbers from tracer.options().sampler.
RenderResult render_paths(const PathTracer& tracer, const PinholeCamera& camera,
                          const RenderSettings& settings);

}  // namespace rt
