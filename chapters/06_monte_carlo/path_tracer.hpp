// An iterative path tracer. The recursion of chapter 05, L(x, wo) = Le + ∫ f L(x', −wi) |cos θ| dω, unrolled
// into a loop that carries the path throughput β = Π f |cos θ| / pdf:
//   L = Σ_k β_k (Le_k [+ next-event estimate at vertex k]),   β_{k+1} = β_k f(wo, wi) |cos θ_i| / pdf(wi),
// with the direction at each vertex drawn by the chosen SamplingStrategy, and chapter 05's Russian roulette
// ending it without bias: survive with probability q, then β /= q. A loop keeps no stack of frames, so a long
// path costs no memory, and the state the compiler keeps in registers is small.
// It reads every material through the Bsdf interface and the material table: a BSDF with transmission sends
// the path through the surface, a delta BSDF is followed like a mirror (what it meets next counts in full),
// and what fills the inside of a shape attenuates the segment that crosses it. Its steps are public, so
// that other loops are built from them: the next-event estimate, the MIS weight of light a path meets, the
// BSDF-sampled continuation and Russian roulette.
#pragma once

#include <cmath>
#include <optional>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/hit.hpp"
#include "02_intersection/world.hpp"
#include "03_shadow_rays/shadow_ray.hpp"
#include "04_direct_lighting/bsdf.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/light_picker.hpp"
#include "04_direct_lighting/light_set.hpp"
#include "04_direct_lighting/material_table.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "04_direct_lighting/trace_options.hpp"
#include "05_recursive_gi/termination.hpp"
#include "environment.hpp"
#include "mis.hpp"
#include "path_observer.hpp"
#include "render_paths.hpp"
#include "rt/core/random.hpp"
#include "rt/core/ray_counts.hpp"
#include "sample_stream.hpp"
#include "sampling_strategy.hpp"

namespace rt {

// Effects read: "direct" (light arriving from emitters at surfaces), "shadows" (shadow rays; without it every
// light sample counts as visible), "indirect" (light after more than one diffuse or glossy bounce). The
// material table holds what "glossy", "reflection" and "refraction" change.
// Where this chapter's roulette starts: bounce 8, not chapter 05's 3. With next-event estimation and MIS the
// first bounces are cheap and carry most of the light; a roulette that starts sooner multiplies the few paths
// it keeps by 1 / q, and that noise costs more time than the bounces it saves (lesson 06, § "Where roulette
// starts").
inline constexpr int kPathRouletteStart = 8;

struct PathOptions : TraceOptions {
    SamplingStrategy strategy = SamplingStrategy::kMis;
    // Chapter 05's Russian roulette from bounce kPathRouletteStart, under its safety cap of 64 bounces (a
    // cap, not a bias).
    TerminationSettings termination{Termination::kRussianRoulette, kSafetyDepthCap, Real(0.01),
                                    kPathRouletteStart};
    // Where a sample's numbers come from (sample_stream.hpp; render_paths reads it).
    PointSet sampler = PointSet::kSobol;
};

// The vertex a ray left, as the MIS weight of the light it meets needs it.
struct PathVertex {
    Vec3 point{0};
    Vec3 normal{0};
    Real pdf = 0;          // the density the ray's direction was drawn with
    bool specular = true;  // the camera, or a delta bounce: what the ray meets counts in full
};

// The direction that continues a path, and the cosine that weighs it.
struct Continuation {
    BsdfSample sample;
    Real cos_i = 0;
};

class PathTracer {
  public:
    // `world` and `materials` must outlive it.
    PathTracer(const World& world, const MaterialTable& materials, const LightSet& lights,
               PathOptions options);

    // The radiance arriving along `ray` (a camera ray): one path, its estimate of L. `observer`, if any, is
    // told what happens along it (path_observer.hpp).
    Color radiance(const Ray& ray, SampleStream rng, RayCounts& rays, PathObserver* observer = nullptr) const;

    // The steps of the loop.
    // The next-event estimate at `hit`: one light picked by power (an area light weighted for MIS; a point
    // light is a delta, weight 1) and the environment (one direction it draws), each with its shadow
    // ray, whose transmittance `seen(ray, t_max, rays)` says (unoccluded: chapter 03's visibility).
    template <class Seen>
    Color next_event(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, SampleStream rng, RayCounts& rays,
                     const Seen& seen) const;
    // The same, its shadow rays unoccluded() or not.
    Color next_event(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, SampleStream rng,
                     RayCounts& rays) const;
    // What a shadow ray sees of the light at t_max: 1 when nothing blocks it, 0 otherwise.
    Color unoccluded(const Ray& ray, Real t_max, RayCounts& rays) const;
    // The MIS weight of light met by a ray from `from` that the next-event estimate there would have drawn
    // with density `light_pdf`: 1 after the camera or a delta bounce, or without next-event estimation; the
    // power heuristic under MIS; 0 under the light strategy (its estimate already counted that light).
    Real met_weight(const PathVertex& from, Real light_pdf) const;
    // The MIS weight of the emitter `hit` that `ray` from `from` meets (an emissive plane is none, Hit::light
    // = −1: light sampling cannot find it, so it counts in full).
    Real emitter_weight(const PathVertex& from, const Ray& ray, const Hit& hit) const;
    // The BSDF-sampled continuation at `hit`: the direction the strategy draws (the BSDF's own sampling with
    // next-event estimation, at a delta BSDF, and under the BSDF strategy; the uniform or cosine hemisphere
    // otherwise); none when it carries nothing.
    std::optional<Continuation> continuation(const Hit& hit, const Vec3& wo, const Bsdf& bsdf,
                                             SampleStream rng) const;
    // Russian roulette after `depth` bounces, judged on β × eta_scale (the product of the samples'
    // 1 / roulette_scale: a path through a refracting surface is judged on what it carries back out):
    // survive with q, then β /= q.
    bool roulette(int depth, Color& beta, Real eta_scale, SampleStream rng) const;

    // Whether the strategy and effects make next-event estimates, weigh them by MIS, count direct and
    // indirect light.
    bool estimates() const { return nee_; }
    bool weighs() const { return mis_; }
    bool direct() const { return direct_; }
    bool indirect() const { return indirect_; }
    // Some emitter (an emissive plane) that next-event estimation cannot sample.
    bool has_unsampled_emitters() const { return has_unsampled_emitters_; }
    const PathOptions& options() const { return options_; }
    const MaterialTable& materials() const { return materials_; }
    const LightPicker& lights() const { return picker_; }
    const std::optional<Environment>& environment() const { return environment_; }

  private:
    // The transmittance of the segment that ends at `hit`: what fills the inside of a shape attenuates it
    // when it ends on the back of a surface that lets light through; 1 elsewhere.
    Color segment_transmittance(const Hit& hit) const;

    const World& world_;
    const MaterialTable& materials_;
    LightPicker picker_;
    std::optional<Environment> environment_;
    bool has_unsampled_emitters_;  // an emissive plane: only paths that hit it see it
    PathOptions options_;
    bool direct_, indirect_, nee_, mis_;
};

// Inline: it runs at every vertex, and the loops that call it keep its sample in registers.
inline std::optional<Continuation> PathTracer::continuation(const Hit& hit, const Vec3& wo, const Bsdf& bsdf,
                                                            SampleStream rng) const {
    const BsdfFlags& flags = bsdf.flags();
    const Vec3& n = hit.shading_normal;
    Continuation c;
    BsdfSample& s = c.sample;
    const Vec2 u = rng.next_vec2();
    if (flags.delta || options_.strategy == SamplingStrategy::kBrdf || nee_) {
        // A BSDF with two lobes (reflection and transmission) takes one more number to choose between them.
        s = bsdf.sample(wo, n, u, flags.transmission ? rng.next_real() : Real(0));
    } else {
        const bool uniform = options_.strategy == SamplingStrategy::kUniform;
        const Vec3 local = uniform ? sample_uniform_hemisphere(u) : sample_cosine_hemisphere(u);
        s.wi = glm::normalize(make_frame(n).to_world(local));
        s.pdf = uniform ? uniform_hemisphere_pdf(local) : cosine_hemisphere_pdf(local.z);
        s.f = bsdf.eval(wo, s.wi, n);
    }
    c.cos_i = scattering_cosine(s.wi, n, s.transmitted);
    if (!(c.cos_i > 0) || !(s.pdf > 0) || is_black(s.f)) return std::nullopt;
    return c;
}

template <class Seen>
Color PathTracer::next_event(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, SampleStream rng,
                             RayCounts& rays, const Seen& seen) const {
    const bool shadows = options_.simulates(Effect::kShadows);
    // A BSDF that transmits is lit from both sides; |cos θ_i| then weighs light from behind the surface.
    const bool both_sides = bsdf.flags().transmission;
    const Vec3& n = hit.shading_normal;
    Color sum(0);
    if (!picker_.empty()) {
        // With one light there is nothing to choose, and no number to draw.
        const Real u_pick = picker_.light_count() > 1 ? rng.next_real() : Real(0);
        const Vec2 u = rng.next_vec2();
        if (const auto s = picker_.sample(hit.point, u_pick, u)) {
            const Real dot_i = glm::dot(s->wi, n);
            const Real cos_i = both_sides ? std::abs(dot_i) : dot_i;
            if (cos_i > 0 && s->pdf > 0) {
                const Color f = bsdf.eval(wo, s->wi, n);
                Color T(1);
                if (!is_black(f) && shadows) {
                    const ShadowRay shadow = spawn_shadow_ray(hit, s->point, options_.offset);
                    T = seen(shadow.ray, shadow.t_max, rays);
                }
                if (!is_black(f) && !is_black(T)) {
                    // A point light is a delta: no BSDF sample can hit it, so its light sample has weight 1.
                    const Real w =
                        mis_ && s->on_surface() ? power_heuristic(s->pdf, bsdf.pdf(wo, s->wi, n)) : Real(1);
                    sum += f * T * s->radiance * (cos_i * w / s->pdf);
                }
            }
        }
    }
    if (environment_) {
        // The environment: a direction it draws (environment.hpp: cosine-weighted for a constant, by
        // importance for an image), its shadow ray to infinity.
        const EnvironmentSample s = environment_->sample(n, rng.next_vec2());
        const Real dot_i = glm::dot(s.wi, n);
        const Real cos_i = both_sides ? std::abs(dot_i) : dot_i;
        const Color f = cos_i > 0 && s.pdf > 0 ? bsdf.eval(wo, s.wi, n) : Color(0);
        if (!is_black(f)) {
            const Color T = shadows ? seen(spawn_ray(hit, s.wi, options_.offset), kInfinity, rays) : Color(1);
            if (!is_black(T)) {
                const Real w = mis_ ? power_heuristic(s.pdf, bsdf.pdf(wo, s.wi, n)) : Real(1);
                sum += f * T * s.radiance * (cos_i * w / s.pdf);
            }
        }
    }
    return sum;
}

}  // namespace rt
