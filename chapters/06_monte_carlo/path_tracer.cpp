#include "path_tracer.hpp"

namespace rt {

PathTracer::PathTracer(const World& world, const MaterialTable& materials, const LightSet& lights,
                       PathOptions options)
    : world_(world),
      materials_(materials),
      picker_(lights, options.quad_lights),
      environment_(lights.environment ? std::optional<Environment>(*lights.environment) : std::nullopt),
      has_unsampled_emitters_(!lights.unsampled.empty()),
      options_(options),
      direct_(options.simulates(Effect::kDirect)),
      indirect_(options.simulates(Effect::kIndirect)),
      nee_(direct_ && samples_lights(options.strategy)),
      mis_(options.strategy == SamplingStrategy::kMis) {
    if (environment_ && environment_->black()) environment_.reset();
}

Color PathTracer::unoccluded(const Ray& ray, Real t_max, RayCounts& rays) const {
    rays.add(RayKind::kShadow);
    return Color(world_.occluded(ray, t_max) ? 0 : 1);
}

Color PathTracer::segment_transmittance(const Hit& hit) const {
    if (hit.front_face) return Color(1);
    const auto* filling = materials_.interior(hit.material);
    if (!filling || !materials_.bsdf(hit.material, false).flags().transmission) return Color(1);
    return filling->transmittance(hit.t);
}

Real PathTracer::met_weight(const PathVertex& from, Real light_pdf) const {
    if (from.specular || !nee_) return 1;
    return mis_ ? power_heuristic(from.pdf, light_pdf) : Real(0);
}

Real PathTracer::emitter_weight(const PathVertex& from, const Ray& ray, const Hit& hit) const {
    if (from.specular || !nee_ || hit.light < 0) return 1;
    return met_weight(from, picker_.pdf(from.point, ray.direction, hit));
}

bool PathTracer::roulette(int depth, Color& beta, Real eta_scale, SampleStream rng) const {
    // A number is drawn only from the bounce where Russian roulette starts (a Sobol draw costs a pair's
    // hashes): before it, and under the depth and throughput rules, q is 0 or 1, and u = 0 decides the same.
    const TerminationSettings& rule = options_.termination;
    const bool by_chance = rule.rule == Termination::kRussianRoulette && depth >= rule.roulette_start_depth;
    return continue_path(rule, depth, beta, by_chance ? rng.next_real() : Real(0), eta_scale);
}

Color PathTracer::radiance(const Ray& ray, SampleStream rng, RayCounts& rays, PathObserver* observer) const {
    PathState path;
    trace(ray, path, rng, rays, observer, SurfacePaths(*this));
    return path.L;
}

}  // namespace rt
