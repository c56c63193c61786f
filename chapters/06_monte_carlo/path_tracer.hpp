// An iterative path tracer. The recursion of chapter 05, L(x, wo) = Le + ∫ f L(x', −wi) |cos θ| dω, unrolled
// into a loop that carries the path throughput β = Π f |cos θ| / pdf:
//   L = Σ_k β_k (Le_k [+ next-event estimate at vertex k]),   β_{k+1} = β_k f(wo, wi) |cos θ_i| / pdf(wi),
// with the direction at each vertex drawn by the chosen SamplingStrategy, and chapter 05's Russian roulette
// ending it without bias: survive with probability q, then β /= q. A loop keeps no stack of frames, so a long
// path costs no memory, and the state the compiler keeps in registers is small.
// It reads every material through the Bsdf interface and the material table: a BSDF with transmission sends
// the path through the surface, a delta BSDF is followed like a mirror (what it meets next counts in full),
// and what fills the inside of a shape attenuates the segment that crosses it. A later chapter extends the
// loop without copying it: an extension (SurfacePaths is this chapter's) says what happens between two
// vertices and at one, and its vertex (bsdf_vertex.hpp) how the continuation is drawn and with what density.
// The steps are public: the next-event estimate, the MIS weight of light a path meets, Russian roulette.
#pragma once

#include <cmath>
#include <concepts>
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
#include "bsdf_vertex.hpp"
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

// The state of one path, carried by the loop (PathTracer::trace) from vertex to vertex.
struct PathState {
    Color L{0}, beta{1};
    PathVertex from;     // the vertex the ray left: the camera first
    int bounces = 0;     // non-delta bounces so far
    int depth = 0;       // bounces so far, delta ones too (what roulette counts)
    Real eta_scale = 1;  // Π of the samples' 1 / roulette_scale
    // L grows by light the path met (an emitter, the environment) and by next-event estimates. The loop is a
    // template over the path's type: a study that files each term (PathParts) derives and hides these two.
    void add_met(const Color& term) { L += term; }
    void add_estimate(const Color& term) { L += term; }
};

// What became of the path between two vertices (PathExtension::segment).
enum class Segment {
    kReached,    // it reached what the ray hit (none: it left the scene)
    kScattered,  // it scattered on the way (in a medium): the ray now leaves that vertex
    kEnded,
};

// The extension point. PathTracer::trace runs the loop with an extension `ext` that says, by these members
// (SurfacePaths below is chapter 06's, chapter 09's VolumePathTracer another):
//   Segment segment(Ray& ray, const std::optional<Hit>& hit, Path& path, SampleStream, RayCounts&): the
//                   step between two vertices, along `ray` to `hit`;
//   bool crosses(const Hit&, Ray& ray, RayCounts&): the path crosses the surface without a vertex (true:
//                   `ray` goes on beyond it);
//   auto vertex(const Hit&, const Vec3& wo, const Bsdf&): the surface vertex (bsdf_vertex.hpp), which draws
//                   the continuation and gives the density MIS weighs with;
//   Color seen(const Ray&, Real t_max, RayCounts&): what a shadow ray sees of the light at t_max;
//   bool survives(const Hit&, Path& path, SampleStream): after a surface bounce, whether the path goes on.
class SurfacePaths;

class PathTracer {
  public:
    // `world` and `materials` must outlive it.
    PathTracer(const World& world, const MaterialTable& materials, const LightSet& lights,
               PathOptions options);

    // The radiance arriving along `ray` (a camera ray): one path, its estimate of L. `observer`, if any, is
    // told what happens along it (path_observer.hpp).
    Color radiance(const Ray& ray, SampleStream rng, RayCounts& rays, PathObserver* observer = nullptr) const;
    // The same, the path's state kept in `path`: a type derived from PathState (a study's that files the
    // terms of L, PathParts), fresh.
    template <std::derived_from<PathState> Path>
    Color radiance(const Ray& ray, SampleStream rng, RayCounts& rays, Path* path) const;

    // The loop: the path from `ray` on, its state in `path`, its steps between and at vertices as `ext` says.
    template <class Path, class Extension>
    void trace(Ray ray, Path& path, SampleStream rng, RayCounts& rays, PathObserver* observer,
               const Extension& ext) const;

    // The steps of the loop.
    // The next-event estimate at `vertex` (bsdf_vertex.hpp): one light picked by power (an area light
    // weighted for MIS; a point light is a delta, weight 1) and the environment (one direction it draws),
    // each with its shadow ray, whose transmittance ext.seen(ray, t_max, rays) says.
    template <class Vertex, class Extension>
    Color next_event(const Vertex& vertex, SampleStream rng, RayCounts& rays, const Extension& ext) const;
    // Its lights' part, from the light sample (u_pick, u); `weight` scales it (chapter 09's distance MIS).
    template <class Vertex, class Extension>
    Color light_estimate(const Vertex& vertex, Real u_pick, Vec2 u, Real weight, RayCounts& rays,
                         const Extension& ext) const;
    // Its environment's part (0 without an environment).
    template <class Vertex, class Extension>
    Color environment_estimate(const Vertex& vertex, SampleStream rng, RayCounts& rays,
                               const Extension& ext) const;
    // What a shadow ray sees of the light at t_max: 1 when nothing blocks it, 0 otherwise.
    Color unoccluded(const Ray& ray, Real t_max, RayCounts& rays) const;
    // The transmittance of the segment that ends at `hit`: what fills the inside of a shape attenuates it
    // when it ends on the back of a surface that lets light through; 1 elsewhere.
    Color segment_transmittance(const Hit& hit) const;
    // The MIS weight of light met by a ray from `from` that the next-event estimate there would have drawn
    // with density `light_pdf`: 1 after the camera or a delta bounce, or without next-event estimation; the
    // power heuristic under MIS; 0 under the light strategy (its estimate already counted that light).
    Real met_weight(const PathVertex& from, Real light_pdf) const;
    // The MIS weight of the emitter `hit` that `ray` from `from` meets (an emissive plane is none, Hit::light
    // = −1: light sampling cannot find it, so it counts in full).
    Real emitter_weight(const PathVertex& from, const Ray& ray, const Hit& hit) const;
    // Whether light met by a ray from `from` can count at all: after the camera or a delta bounce, or when
    // direct light is simulated and the met light is not all next-event estimation's (MIS, the BSDF strategy,
    // or an emitter it cannot sample).
    bool counts_met_light(const PathVertex& from) const {
        return from.specular || (direct_ && (!nee_ || mis_ || has_unsampled_emitters_));
    }
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
    const World& world_;
    const MaterialTable& materials_;
    LightPicker picker_;
    std::optional<Environment> environment_;
    bool has_unsampled_emitters_;  // an emissive plane: only paths that hit it see it
    PathOptions options_;
    bool direct_, indirect_, nee_, mis_;
};

// Chapter 06's paths: between two surfaces only what fills a shape (it attenuates the segment), at each
// surface the BSDF's vertex, chapter 03's shadow rays and chapter 05's roulette. A later chapter's extension
// may derive from it and hide the members it changes (the loop is a template: no virtual call).
class SurfacePaths {
  public:
    explicit SurfacePaths(const PathTracer& tracer) : tracer_(tracer) {}

    Segment segment(Ray& /*ray*/, const std::optional<Hit>& hit, PathState& path, SampleStream /*rng*/,
                    RayCounts& /*rays*/) const {
        if (hit) path.beta *= tracer_.segment_transmittance(*hit);
        return Segment::kReached;
    }
    bool crosses(const Hit& /*hit*/, Ray& /*ray*/, RayCounts& /*rays*/) const { return false; }
    BsdfVertex vertex(const Hit& hit, const Vec3& wo, const Bsdf& bsdf) const {
        const PathOptions& options = tracer_.options();
        return {hit, wo, bsdf, options.strategy, tracer_.estimates(), options.offset};
    }
    Color seen(const Ray& ray, Real t_max, RayCounts& rays) const {
        return tracer_.unoccluded(ray, t_max, rays);
    }
    bool survives(const Hit& /*hit*/, PathState& path, SampleStream rng) const {
        return tracer_.roulette(++path.depth, path.beta, path.eta_scale, rng);
    }

  protected:
    const PathTracer& tracer_;
};

template <std::derived_from<PathState> Path>
Color PathTracer::radiance(const Ray& ray, SampleStream rng, RayCounts& rays, Path* path) const {
    trace(ray, *path, rng, rays, nullptr, SurfacePaths(*this));
    return path->L;
}

template <class Path, class Extension>
void PathTracer::trace(Ray ray, Path& path, SampleStream rng, RayCounts& rays, PathObserver* observer,
                       const Extension& ext) const {
    // EXERCISE(ch06.path_tracer) § The path tracer
    BsdfAtHit at;           // a textured material's BSDF at the vertex
    bool last_ray = false;  // the ray drawn at the depth cap: it adds the light it meets, nothing after
    for (;;) {
        const auto hit = world_.intersect(ray);
        const Segment segment = ext.segment(ray, hit, path, rng, rays);
        if (segment == Segment::kScattered) continue;
        if (segment == Segment::kEnded) break;
        // Light the path meets: counted in full after the camera or a delta bounce, weighted by MIS against
        // the next-event estimate otherwise, and not at all by the light strategy (which counted it there).
        const PathVertex& from = path.from;
        if (!hit) {
            if (environment_ && (from.specular || direct_)) {
                const Real light_pdf = environment_->pdf(from.normal, ray.direction);
                path.add_met(path.beta * environment_->radiance(ray.direction) * met_weight(from, light_pdf));
            }
            break;
        }
        const Color emitted = materials_.emission(hit->material, hit->front_face);
        if (!is_black(emitted) && (from.specular || direct_))
            path.add_met(path.beta * emitted * emitter_weight(from, ray, *hit));
        if (last_ray) break;
        if (!indirect_ && path.bounces >= 1) break;
        const Bsdf& bsdf = materials_.bsdf(*hit, at);
        const BsdfFlags& flags = bsdf.flags();
        if (observer && !observer->reached(*hit, flags, path.bounces)) break;
        if (ext.crosses(*hit, ray, rays)) continue;
        if (flags.black) break;
        const auto vertex = ext.vertex(*hit, -ray.direction, bsdf);
        if (nee_ && !flags.delta) path.add_estimate(path.beta * next_event(vertex, rng, rays, ext));
        // Without the indirect effect the path ends at the vertex it reaches next, where light sampling alone
        // (no MIS) already counted every light it could meet — unless some emitter cannot be sampled.
        if (!indirect_ && !flags.delta && nee_ && !mis_ && !has_unsampled_emitters_) break;
        const std::optional<Continuation> next = vertex.sample(rng);
        if (!next) break;
        const BsdfSample& s = next->sample;
        if (observer) observer->sampled(path.beta, s, next->cos_i);
        path.beta *= s.f * (next->cos_i / s.pdf);
        path.eta_scale /= s.roulette_scale;
        path.from = {hit->point, hit->shading_normal, s.delta ? kInfinity : s.pdf, s.delta};
        if (!s.delta) ++path.bounces;
        if (!ext.survives(*hit, path, rng)) {
            // At the depth cap the drawn ray is still traced, for the light it meets alone: a path of N
            // bounces keeps both strategies' shares of that light (pbrt's maxdepth), and every strategy
            // renders the same depth-N image.
            if (path.depth < options_.termination.max_depth || !counts_met_light(path.from)) break;
            last_ray = true;
        }
        ray = spawn_ray(*hit, s.wi, options_.offset);
        rays.add(ray_kind(flags, s.transmitted));
    }
    // END EXERCISE
}

template <class Vertex, class Extension>
Color PathTracer::next_event(const Vertex& vertex, SampleStream rng, RayCounts& rays,
                             const Extension& ext) const {
    Color sum(0);
    if (!picker_.empty()) {
        // With one light there is nothing to choose, and no number to draw.
        const Real u_pick = picker_.light_count() > 1 ? rng.next_real() : Real(0);
        const Vec2 u = rng.next_vec2();
        sum += light_estimate(vertex, u_pick, u, Real(1), rays, ext);
    }
    sum += environment_estimate(vertex, rng, rays, ext);
    return sum;
}

template <class Vertex, class Extension>
Color PathTracer::light_estimate(const Vertex& vertex, Real u_pick, Vec2 u, Real weight, RayCounts& rays,
                                 const Extension& ext) const {
    const auto s = picker_.sample(vertex.point(), u_pick, u);
    if (!s || !(s->pdf > 0)) return Color(0);
    const Scattering f = vertex.toward(s->wi);
    if (f.none()) return Color(0);
    Color T(1);
    if (options_.simulates(Effect::kShadows)) {
        const ShadowRay shadow = vertex.shadow_ray(*s);
        T = ext.seen(shadow.ray, shadow.t_max, rays);
        if (is_black(T)) return Color(0);
    }
    // A point light is a delta: no BSDF sample can hit it, so its light sample has weight 1.
    const Real w = mis_ && s->on_surface() ? power_heuristic(s->pdf, vertex.pdf(s->wi)) : Real(1);
    return f.f * T * s->radiance * (f.cos * (w * weight) / s->pdf);
}

template <class Vertex, class Extension>
Color PathTracer::environment_estimate(const Vertex& vertex, SampleStream rng, RayCounts& rays,
                                       const Extension& ext) const {
    if (!environment_) return Color(0);
    // A direction the environment draws (environment.hpp: cosine-weighted about the normal for a constant,
    // uniform over the sphere where there is none; by importance for an image), its shadow ray to infinity.
    const EnvironmentSample s = environment_->sample(vertex.normal(), rng.next_vec2());
    const Scattering f = s.pdf > 0 ? vertex.toward(s.wi) : Scattering{};
    if (f.none()) return Color(0);
    const Color T =
        options_.simulates(Effect::kShadows) ? ext.seen(vertex.ray(s.wi), kInfinity, rays) : Color(1);
    if (is_black(T)) return Color(0);
    const Real w = mis_ ? power_heuristic(s.pdf, vertex.pdf(s.wi)) : Real(1);
    return f.f * T * s.radiance * (f.cos * w / s.pdf);
}

}  // namespace rt
