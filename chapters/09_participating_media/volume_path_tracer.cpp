#include "volume_path_tracer.hpp"

#include <cmath>
#include <limits>

#include "01_ray_generation/camera.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "equiangular.hpp"

namespace rt {

namespace {

// A walk's Russian roulette: chapter 05's rule from its first event, under no depth cap.
constexpr TerminationSettings kWalkRoulette{.rule = Termination::kRussianRoulette,
                                            .max_depth = std::numeric_limits<int>::max(),
                                            .roulette_start_depth = 0};

}  // namespace

VolumePathTracer::VolumePathTracer(const World& world, const MaterialTable& materials, const LightSet& lights,
                                   PathOptions options, MediumWalk walk)
    : steps_(world, materials, lights, options),
      targets_(lights, QuadLightSampling::kArea),
      world_(world),
      materials_(materials),
      exterior_{materials.exterior(), dynamic_cast<const ScatteringMedium*>(materials.exterior())},
      media_(exterior_.medium != nullptr),
      walk_(walk) {
    for (std::size_t m = 0; m < materials.size(); ++m) {
        const Medium* inside = materials.interior(int(m));
        interiors_.push_back({inside, dynamic_cast<const ScatteringMedium*>(inside)});
        index_matched_.push_back(index_matched(materials.bsdf(int(m))));
        media_ = media_ || interiors_.back().scattering;
    }
}

VolumePathTracer::Filling VolumePathTracer::medium_along(const std::optional<Hit>& end) const {
    if (end && !end->front_face && materials_.bsdf(end->material, false).flags().transmission)
        return interiors_[std::size_t(end->material)];
    return exterior_;
}

Color VolumePathTracer::transmittance(Ray ray, Real t_max, RayCounts& rays) const {
    // T = Π over the segments of exp(−σ_t d): each segment through the medium its end says, to the next
    // surface before t_max, which the ray crosses only if it is an index-matched boundary.
    Color T(1);
    for (;;) {
        rays.add(RayKind::kShadow);
        const auto hit = world_.intersect(ray, t_max);
        if (const Medium* medium = medium_along(hit).medium) T *= medium->transmittance(hit ? hit->t : t_max);
        if (!hit) return T;
        if (!index_matched_[std::size_t(hit->material)] || is_black(T)) return Color(0);
        t_max -= hit->t;
        ray = spawn_ray(*hit, ray.direction, steps_.options().offset);
    }
}

Color VolumePathTracer::seen(const Ray& ray, Real t_max, RayCounts& rays) const {
    return media_ ? transmittance(ray, t_max, rays) : steps_.unoccluded(ray, t_max, rays);
}

Color VolumePathTracer::next_event_in_medium(const PhaseVertex& vertex, SampleStream rng, RayCounts& rays,
                                             const std::optional<LitSegment>& lit) const {
    Color sum(0);
    if (!steps_.lights().empty()) {
        const Real u_pick = rng.next_real();
        const Vec2 u = rng.next_vec2();
        // w_ff(t) = 1 under free flight alone (no `lit`): the estimate is chapter 09's, to the bit.
        const Real w = lit ? free_flight_weight(walk_.distance, free_flight_pdf(lit->sigma_t(), lit->t_event),
                                                equiangular_pdf(*lit, lit->t_event, u_pick, u))
                           : Real(1);
        if (w > 0) sum += steps_.light_estimate(vertex, u_pick, u, w, rays, *this);
    }
    sum += steps_.environment_estimate(vertex, rng, rays, *this);
    return sum;
}

std::optional<LitSegment> VolumePathTracer::lit_segment(const Medium& medium, const Ray& ray,
                                                        Real t_max) const {
    if (walk_.distance == DistanceSampling::kFreeFlight || !steps_.estimates() || steps_.lights().empty() ||
        !std::isfinite(t_max))
        return std::nullopt;
    const auto* homogeneous = dynamic_cast<const HomogeneousMedium*>(&medium);
    if (!homogeneous) return std::nullopt;
    const Color& sigma_t = homogeneous->sigma_t;
    if (sigma_t.r != sigma_t.g || sigma_t.g != sigma_t.b || !(sigma_t.r > 0)) return std::nullopt;
    return LitSegment{ray, t_max, homogeneous, 0};
}

std::optional<Vec3> VolumePathTracer::equiangular_target(const LitSegment& lit, Real u_pick, Vec2 u) const {
    const auto s = targets_.sample(lit.ray.origin, u_pick, u);
    return s ? std::optional<Vec3>(s->point) : std::nullopt;
}

Real VolumePathTracer::equiangular_pdf(const LitSegment& lit, Real t, Real u_pick, Vec2 u) const {
    const auto target = equiangular_target(lit, u_pick, u);
    if (!target) return 0;
    const auto sampler = EquiangularSampler::toward(lit.ray, *target, lit.t_max);
    return sampler ? sampler->pdf(t) : Real(0);
}

Color VolumePathTracer::in_scattered_equiangular(const LitSegment& lit, SampleStream rng,
                                                 RayCounts& rays) const {
    // ∫ T(t) σ_s L_light(x(t)) dt ≈ T(t) σ_s L̂_light(x(t)) w_eq(t) / p_eq(t), t ~ p_eq, the numbers
    // (u_pick, u) both aiming the sampler and, from x(t), drawing the light sample that estimates L_light.
    const Real u_pick = rng.next_real();
    const Vec2 u = rng.next_vec2();
    const Real u_t = rng.next_real();
    const auto target = equiangular_target(lit, u_pick, u);
    if (!target) return Color(0);
    const auto sampler = EquiangularSampler::toward(lit.ray, *target, lit.t_max);
    if (!sampler) return Color(0);
    const Real t = sampler->sample(u_t);
    const Real p_eq = sampler->pdf(t);
    if (!(p_eq > 0)) return Color(0);
    const Real w = equiangular_weight(walk_.distance, free_flight_pdf(lit.sigma_t(), t), p_eq);
    const PhaseVertex vertex(lit.ray.at(t), -lit.ray.direction, lit.medium->phase());
    const Color L = steps_.light_estimate(vertex, u_pick, u, w / p_eq, rays, *this);
    return lit.medium->transmittance(t) * lit.medium->sigma_s * L;
}

FreeFlight VolumePathTracer::fly(const Filling& filling, Real t_max, VolumePath& path,
                                 SampleStream rng) const {
    // The distance is a draw of the sample's stream, so Sobol points stratify the choice between the medium
    // and the surface beyond. A medium that only absorbs draws no number: its flight always reaches t_max.
    const ScatteringMedium* scattering = filling.scattering;
    if (scattering && path.channel < 0) path.channel = pick_channel(rng.next_real());
    const FreeFlight flight = scattering
                                  ? scattering->sample_free_flight(t_max, path.channel, rng.next_real())
                                  : FreeFlight{false, t_max, filling.medium->transmittance(t_max), Color(1)};
    path.beta *= flight.weight;
    if (flight.pdf_ratio != Color(1)) {
        path.spectral_pdf *= flight.pdf_ratio;
        const Real mean = (path.spectral_pdf.r + path.spectral_pdf.g + path.spectral_pdf.b) / 3;
        path.beta /= mean;
        path.spectral_pdf /= mean;
    }
    return flight;
}

bool VolumePathTracer::scatter_in_medium(const PhaseFunction& phase, Ray& ray, Real t, VolumePath& path,
                                         SampleStream rng, RayCounts& rays,
                                         const std::optional<LitSegment>& lit) const {
    // EXERCISE(ch09.volume_vertex) § 5. The volumetric path loop
    const Vec3 p = ray.at(t);
    const PhaseVertex vertex(p, -ray.direction, phase);
    if (steps_.estimates()) path.add_estimate(path.beta * next_event_in_medium(vertex, rng, rays, lit));
    const PhaseSample s = vertex.sample(rng);
    if (!(s.pdf > 0) || !(s.p > 0)) return false;
    path.beta *= s.p / s.pdf;
    ++path.bounces;
    path.from = {p, Vec3(0), s.pdf, false};
    if (walk_.roulette && !continue_path(kWalkRoulette, path.events, path.beta, rng.next_real()))
        return false;
    ray = Ray{p, s.wi};
    rays.add(RayKind::kIndirect);
    return true;
    // END EXERCISE
}

Segment VolumePathTracer::segment(Ray& ray, const std::optional<Hit>& hit, VolumePath& path, SampleStream rng,
                                  RayCounts& rays) const {
    // What fills the segment: a medium that only absorbs attenuates it; one that scatters may end it early,
    // at a vertex in the volume.
    const Filling filling = medium_along(hit);
    if (!filling.medium) return Segment::kReached;
    const Color beta = path.beta;  // before the flight
    const FreeFlight flight = fly(filling, hit ? hit->t : kInfinity, path, rng);
    // The segment's equiangular point, a vertex as deep as the free-flight event would be.
    std::optional<LitSegment> lit = lit_segment(*filling.medium, ray, hit ? hit->t : kInfinity);
    const bool indirect = steps_.indirect();
    if (lit && (indirect || path.bounces == 0) && path.events < walk_.max_events)
        path.add_estimate(beta * in_scattered_equiangular(*lit, rng, rays));
    if (!flight.scattered) return Segment::kReached;
    if ((!indirect && path.bounces >= 1) || ++path.events > walk_.max_events) return Segment::kEnded;
    if (lit) lit->t_event = flight.t;
    return scatter_in_medium(filling.scattering->phase(), ray, flight.t, path, rng, rays, lit)
               ? Segment::kScattered
               : Segment::kEnded;
}

bool VolumePathTracer::crosses(const Hit& hit, Ray& ray, RayCounts& rays) const {
    if (!media_ || !index_matched_[std::size_t(hit.material)]) return false;
    ray = spawn_ray(hit, ray.direction, steps_.options().offset);
    rays.add(RayKind::kRefraction);
    return true;
}

bool VolumePathTracer::survives(const Hit& hit, VolumePath& path, SampleStream rng) const {
    if (!hit.front_face && interiors_[std::size_t(hit.material)].scattering)
        return ++path.events <= walk_.max_events;
    return steps_.roulette(++path.depth, path.beta, path.eta_scale, rng);
}

Color VolumePathTracer::radiance(const Ray& ray, SampleStream rng, RayCounts& rays,
                                 PathObserver* observer) const {
    VolumePath path;
    steps_.trace(ray, path, rng, rays, observer, *this);
    return path.L;
}

RenderResult render_with_media(Renderer renderer, const Scene& scene, const EffectSet& simulated,
                               const RenderSettings& settings, PathOptions options, MediumWalk walk,
                               const MaterialHooks& hooks) {
    // A run that simulates no media has nothing for this loop to add: chapter 07's renders it (the same
    // image, to the bit, as the test of this loop without media shows).
    if (renderer == Renderer::kDirect || !simulated.contains(Effect::kMedia))
        return render_with(renderer, scene, simulated, settings, options, hooks);
    const RenderScene prepared(scene, simulated, hooks);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
    options.simulated = simulated;
    const VolumePathTracer tracer(prepared.world, prepared.materials, prepared.lights, options, walk);
    return render_paths(tracer, camera, settings);
}

}  // namespace rt
