// Chapter 06's path loop made volumetric (pbrt-v4's VolPathIntegrator beside its PathIntegrator): this tracer
// is an extension of chapter 06's loop (path_tracer.hpp, PathTracer::trace), which runs every surface vertex
// as chapter 06 does, and calls this chapter's steps where a path meets a medium:
//   - free flight: along each segment, the medium that fills it samples the distance to a scattering event,
//     drawn with one colour channel's density, spectral MIS over the whole path keeping the weight bounded;
//   - the vertex in the volume: the phase function in the place of the BSDF, no surface, no cosine;
//   - next-event estimation through media: shadow rays carry the transmittance of the media they cross,
//     across index-matched boundaries (which the path also crosses without a vertex);
//   - the walk inside a dielectric's medium (subsurface scattering), ended by its own two knobs;
//   - optionally, equiangular distance sampling of the light scattered along a segment, alone or by MIS with
//     free flight (distance_sampling.hpp).
// A scene without media draws the random numbers chapter 06's loop draws, and renders the same image.
#pragma once

#include <optional>
#include <vector>

#include "06_monte_carlo/path_tracer.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "distance_sampling.hpp"
#include "media_materials.hpp"
#include "phase_vertex.hpp"
#include "scattering_medium.hpp"

namespace rt {

// How a path that scatters in a medium ends, and where it looks for light along its segments. Its scattering
// events are not the bounces that chapter 06's `termination` counts (a walk in milk makes hundreds of them):
// they have their own two knobs.
struct MediumWalk {
    int max_events = 10000;  // a hard cap on a path's events in media (scattering, and reflections at a
                             // walk's boundary): a bias when a path meets it
    bool roulette = true;    // Russian roulette at every event: go on with q = min(1, max β), then β /= q
    DistanceSampling distance = DistanceSampling::kFreeFlight;  // the points that look for light
};

// The state of one volumetric path: chapter 06's, where `from` may be a vertex in a medium (normal 0),
// `bounces` counts scattering events too and `depth` (what chapter 06's roulette counts) the surface bounces
// outside walks; and beside it:
struct VolumePath : PathState {
    int events = 0;    // the walks' events so far: scattering, and reflections at a walk's boundary
    int channel = -1;  // the colour channel whose density draws the free flights (-1: none chosen yet)
    // The path's densities under each channel's sampling, relative to the chosen one's, kept at mean 1.
    Color spectral_pdf{1};
};

class VolumePathTracer {
  public:
    // `world` and `materials` must outlive it.
    VolumePathTracer(const World& world, const MaterialTable& materials, const LightSet& lights,
                     PathOptions options, MediumWalk walk = {});

    // The radiance arriving along `ray` (a camera ray): one path, its estimate of L.
    Color radiance(const Ray& ray, SampleStream rng, RayCounts& rays, PathObserver* observer = nullptr) const;

    const PathOptions& options() const { return steps_.options(); }

    // The hooks of chapter 06's loop (path_tracer.hpp, PathExtension).
    // Along a segment: the free flight through the medium that fills it, and a vertex where it scatters.
    Segment segment(Ray& ray, const std::optional<Hit>& hit, VolumePath& path, SampleStream rng,
                    RayCounts& rays) const;
    // An index-matched boundary: shadow rays cross it (transmittance()), so light sampling sees what lies
    // beyond; a path crosses it too, with no vertex there.
    bool crosses(const Hit& hit, Ray& ray, RayCounts& rays) const;
    // A surface vertex is chapter 06's.
    BsdfVertex vertex(const Hit& hit, const Vec3& wo, const Bsdf& bsdf) const {
        return SurfacePaths(steps_).vertex(hit, wo, bsdf);
    }
    // What a shadow ray sees: chapter 06's visibility in a scene without media, the transmittance with them.
    Color seen(const Ray& ray, Real t_max, RayCounts& rays) const;
    // A walk's own boundary met from inside (a medium that scatters fills this side): its reflections and
    // refractions belong to the walk, which ends by the walk's rules, not by chapter 06's roulette.
    bool survives(const Hit& hit, VolumePath& path, SampleStream rng) const;

  private:
    // What fills a segment: its medium (null: nothing), and the same medium when it scatters (null: it only
    // absorbs).
    struct Filling {
        const Medium* medium = nullptr;
        const ScatteringMedium* scattering = nullptr;
    };
    // What fills a segment, judged at its end: the inside of a shape when it ends on the back of a surface
    // that lets light through, the medium between the shapes otherwise.
    Filling medium_along(const std::optional<Hit>& end) const;
    // The free flight through `filling` over [0, t_max): β takes its weight, divided by the mean of the
    // path's relative densities (spectral MIS). A medium that only absorbs draws no number: its flight
    // reaches t_max, weighted by T(t_max).
    FreeFlight fly(const Filling& filling, Real t_max, VolumePath& path, SampleStream rng) const;
    // The vertex at a scattering event at distance t along `ray`: next-event estimation, then the direction
    // drawn from `phase` continues the path (`ray` becomes it). false: the path ends there.
    // `lit`: the segment when equiangular sampling serves it, which weighs this event's estimate.
    bool scatter_in_medium(const PhaseFunction& phase, Ray& ray, Real t, VolumePath& path, SampleStream rng,
                           RayCounts& rays, const std::optional<LitSegment>& lit) const;
    // Chapter 06's next-event estimate at a vertex in a medium, which always draws u_pick (chapter 06's
    // draws it only to choose between lights): with `lit`, the lights' part is weighed by w_ff against the
    // equiangular point of the same segment, drawn from the same numbers.
    Color next_event_in_medium(const PhaseVertex& vertex, SampleStream rng, RayCounts& rays,
                               const std::optional<LitSegment>& lit) const;
    // The segment [0, t_max) of `ray` through `medium`, when the run's distance sampling serves it (a grey
    // medium that scatters, a finite segment, lights to sample, next-event estimation on).
    std::optional<LitSegment> lit_segment(const Medium& medium, const Ray& ray, Real t_max) const;
    // The point x_l the equiangular sampler aims at: the light (u_pick, u) picks, and a point on it by area
    // (seen from the segment's start). Any point of the light serves; one by area costs no spherical
    // rectangle. None when that light's emitting side faces away.
    std::optional<Vec3> equiangular_target(const LitSegment& lit, Real u_pick, Vec2 u) const;
    // p_eq(t): the density of the equiangular sampler that the light sample (u_pick, u) sets up on `lit`
    // (toward equiangular_target); 0 when there is none.
    Real equiangular_pdf(const LitSegment& lit, Real t, Real u_pick, Vec2 u) const;
    // The segment's equiangular point: t ∝ 1 / |x(t) − x_l|², its next-event estimate from the same numbers
    // (u_pick, u), T(t) σ_s w_eq / p_eq(t) (the path's β before the segment multiplies it).
    Color in_scattered_equiangular(const LitSegment& lit, SampleStream rng, RayCounts& rays) const;
    // The transmittance from ray.origin to ray.at(t_max) (a shadow ray): through media, across
    // index-matched boundaries, 0 at any other surface. Counts a shadow ray per segment.
    Color transmittance(Ray ray, Real t_max, RayCounts& rays) const;

    PathTracer steps_;     // chapter 06's loop, which runs with this tracer as its extension
    LightPicker targets_;  // the lights, quads by area: where equiangular_target draws x_l
    const World& world_;
    const MaterialTable& materials_;
    Filling exterior_;                 // the medium between the shapes (null: empty space)
    std::vector<Filling> interiors_;   // per material: what fills its shapes
    std::vector<char> index_matched_;  // per material: an index-matched boundary (index_matched())
    bool media_;                       // a medium between the shapes, or one that scatters inside a shape
    MediumWalk walk_;
};

// Renders as chapter 07's render_with does, with this chapter's volumetric loop for paths and its media on
// the material table. A run that simulates no media is chapter 07's render.
RenderResult render_with_media(Renderer renderer, const Scene& scene, const EffectSet& simulated,
                               const RenderSettings& settings, PathOptions options = {}, MediumWalk walk = {},
                               const MaterialHooks& hooks = media_materials());

}  // namespace rt
