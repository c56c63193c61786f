#include "recursive_tracer.hpp"

#include "03_shadow_rays/ray_offset.hpp"
#include "scatter.hpp"

namespace rt {

RecursiveTracer::RecursiveTracer(const DirectLighting& shading, GiOptions options)
    : shading_(shading),
      options_(options),
      indirect_(shading.options().simulates(Effect::kIndirect)),
      indirect_rays_find_emitters_(!shading.options().simulates(Effect::kDirect) ||
                                   !shading.lights().unsampled.empty()) {}

bool RecursiveTracer::emission_sampled_by_direct(const Hit& hit) const {
    // The hit knows its light: an emissive plane has none (Hit::light = −1), so indirect rays count it.
    return shading_.options().simulates(Effect::kDirect) && hit.light >= 0;
}

Color RecursiveTracer::radiance(const Ray& ray, Pcg32& rng, RayCounts& rays) const {
    return trace(ray, RayKind::kCamera, 0, Color(1), rng, rays);
}

Color RecursiveTracer::trace(const Ray& ray, RayKind kind, int depth, Color throughput, Pcg32& rng,
                             RayCounts& rays) const {
    // EXERCISE(ch05.trace) § The rendering equation, as a recursion
    const auto hit = shading_.world().intersect(ray);
    const bool counts_emission = kind != RayKind::kIndirect;  // camera rays and mirror bounces
    if (!hit) {
        // The environment is light-sampled too (chapter 04 draws cosine-weighted directions toward it).
        const auto& environment = shading_.lights().environment;
        if (!environment || (!counts_emission && shading_.options().simulates(Effect::kDirect)))
            return Color(0);
        return throughput * environment->radiance;
    }
    const MaterialTable& materials = shading_.materials();
    const Color emitted = materials.emission(hit->material, hit->front_face);
    Color L(0);
    if (!is_black(emitted) && (counts_emission || !emission_sampled_by_direct(*hit)))
        L += throughput * emitted;
    // Does the path bounce at this vertex at all? (Russian roulette divides β by q when it does.)
    if (!continue_path(options_.termination, depth, throughput, rng.next_real())) return L;

    const Vec3 wo = -ray.direction;
    BsdfAtHit at;
    const Bsdf& brdf = materials.bsdf(*hit, at);
    const RayOffset& offset = shading_.options().offset;
    // Chapter 05's one delta BRDF is the mirror (its material table makes no glass).
    if (const auto* mirror = is_delta(brdf) ? dynamic_cast<const MirrorBrdf*>(&brdf) : nullptr) {
        const auto s = mirror_scatter(*mirror, wo, hit->shading_normal);
        if (!s) return L;
        rays.add(RayKind::kReflection);
        return L + trace(spawn_ray(*hit, s->wi, offset), RayKind::kReflection, depth + 1,
                         throughput * s->weight, rng, rays);
    }
    if (is_black(brdf)) return L;
    L += throughput * shading_.direct(*hit, wo, rng, rays);
    if (!indirect_) return L;
    // The vertex the indirect ray reaches may not bounce again (depth + 1 is the cap), so there it could only
    // add the emission of an emitter light sampling misses: without one, the ray is not worth tracing.
    if (depth + 1 >= options_.termination.max_depth && !indirect_rays_find_emitters_) return L;
    const auto s = uniform_scatter(brdf, wo, hit->shading_normal, rng.next_vec2());
    if (!s) return L;
    rays.add(RayKind::kIndirect);
    return L + trace(spawn_ray(*hit, s->wi, offset), RayKind::kIndirect, depth + 1, throughput * s->weight,
                     rng, rays);
    // END EXERCISE
}

}  // namespace rt
