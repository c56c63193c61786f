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

Color PathTracer::next_event(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, SampleStream rng,
                             RayCounts& rays) const {
    return next_event(hit, wo, bsdf, rng, rays,
                      [this](const Ray& ray, Real t_max, RayCounts& n) { return unoccluded(ray, t_max, n); });
}

bool PathTracer::roulette(int depth, Color& beta, Real eta_scale, SampleStream rng) const {
    // A number is drawn only from the bounce where Russian roulette starts (a Sobol draw costs a pair's
    // hashes): before it, and under the depth and throughput rules, q is 0 or 1, and u = 0 decides the same.
    const TerminationSettings& rule = options_.termination;
    const bool by_chance = rule.rule == Termination::kRussianRoulette && depth >= rule.roulette_start_depth;
    return continue_path(rule, depth, beta, by_chance ? rng.next_real() : Real(0), eta_scale);
}

Color PathTracer::radiance(const Ray& camera_ray, SampleStream rng, RayCounts& rays,
                           PathObserver* observer) const {
    // EXERCISE(ch06.path_tracer) § The path tracer
    Color L(0), beta(1);
    Ray ray = camera_ray;
    PathVertex from;     // the vertex the ray left: the camera first
    int bounces = 0;     // non-delta bounces so far
    int depth = 0;       // bounces so far, delta ones too (what roulette counts)
    Real eta_scale = 1;  // Π of the samples' 1 / roulette_scale
    BsdfAtHit at;        // a textured material's BSDF at the vertex
    for (;;) {
        const auto hit = world_.intersect(ray);
        // Light the path meets: counted in full after the camera or a delta bounce, weighted by MIS against
        // the next-event estimate otherwise, and not at all by the light strategy (which counted it there).
        if (!hit) {
            if (environment_ && (from.specular || direct_)) {
                const Real light_pdf = environment_->pdf(from.normal, ray.direction);
                L += beta * environment_->radiance(ray.direction) * met_weight(from, light_pdf);
                if (observer) observer->light_met(L, from.specular, bounces);
            }
            break;
        }
        beta *= segment_transmittance(*hit);
        const Color emitted = materials_.emission(hit->material, hit->front_face);
        if (!is_black(emitted) && (from.specular || direct_)) {
            L += beta * emitted * emitter_weight(from, ray, *hit);
            if (observer) observer->light_met(L, from.specular, bounces);
        }
        if (!indirect_ && bounces >= 1) break;
        const Bsdf& bsdf = materials_.bsdf(*hit, at);
        const BsdfFlags& flags = bsdf.flags();
        if ((observer && !observer->reached(*hit, flags, bounces)) || flags.black) break;
        const Vec3 wo = -ray.direction;
        if (nee_ && !flags.delta) {
            L += beta * next_event(*hit, wo, bsdf, rng, rays);
            if (observer) observer->light_estimated(L);
        }
        // Without the indirect effect the path ends at the vertex it reaches next, where light sampling alone
        // (no MIS) already counted every light it could meet — unless some emitter cannot be sampled.
        if (!indirect_ && !flags.delta && nee_ && !mis_ && !has_unsampled_emitters_) break;
        const std::optional<Continuation> next = continuation(*hit, wo, bsdf, rng);
        if (!next) break;
        const BsdfSample& s = next->sample;
        if (observer) observer->sampled(beta, s, next->cos_i);
        beta *= s.f * (next->cos_i / s.pdf);
        eta_scale /= s.roulette_scale;
        from = {hit->point, hit->shading_normal, flags.delta ? kInfinity : s.pdf, flags.delta};
        if (!flags.delta) ++bounces;
        if (!roulette(++depth, beta, eta_scale, rng)) break;
        ray = spawn_ray(*hit, s.wi, options_.offset);
        rays.add(ray_kind(flags, s.transmitted));
    }
    return L;
    // END EXERCISE
}

}  // namespace rt
