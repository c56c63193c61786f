#include "recursive_tracer.hpp"

#include <variant>

#include "ray_offset.hpp"
#include "scatter.hpp"

namespace rt {
namespace {

std::uint32_t plane_count(const Scene& scene) {
    std::uint32_t n = 0;
    for (const Shape& s : scene.shapes) n += std::holds_alternative<PlaneShape>(s.geometry) ? 1u : 0u;
    return n;
}

}  // namespace

RecursiveTracer::RecursiveTracer(const DirectLighting& shading, const Scene& scene, GiOptions options)
    : shading_(shading),
      scene_(scene),
      options_(options),
      first_plane_(std::uint32_t(shading.world().primitive_count()) - plane_count(scene)),
      indirect_rays_find_emitters_(!shading.options().direct || !shading.lights().unsampled.empty()) {}

bool RecursiveTracer::emission_sampled_by_direct(const Hit& hit) const {
    return shading_.options().direct && hit.primitive < first_plane_;
}

Color RecursiveTracer::radiance(const Ray& ray, Pcg32& rng, RayCounts& rays) const {
    return trace(ray, RayKind::kCamera, 0, Color(1), rng, rays);
}

Color RecursiveTracer::trace(const Ray& ray, RayKind kind, int depth, Color throughput, Pcg32& rng,
                             RayCounts& rays) const {
    // EXERCISE(ch05.trace)
    const auto hit = shading_.world().intersect(ray);
    const bool counts_emission = kind != RayKind::kIndirect;  // camera rays and mirror bounces
    if (!hit) {
        // The environment is light-sampled too (chapter 04 draws cosine-weighted directions toward it).
        const auto& environment = shading_.lights().environment;
        if (!environment || (!counts_emission && shading_.options().direct)) return Color(0);
        return throughput * environment->radiance;
    }
    const Material& material = scene_.materials[std::size_t(hit->material)];
    Color L(0);
    if (hit->front_face && material.emissive() && (counts_emission || !emission_sampled_by_direct(*hit))) {
        L += throughput * material.emission;
    }
    // Does the path bounce at this vertex at all? (Russian roulette divides β by q when it does.)
    if (!continue_path(options_.termination, depth, throughput, rng.next_real())) return L;

    const Vec3 wo = -ray.direction;
    const Brdf& brdf = shading_.brdf(hit->material);
    const RayOffset& offset = shading_.options().offset;
    if (const auto* mirror = std::get_if<MirrorBrdf>(&brdf)) {
        if (!options_.reflection) return L;
        const auto s = mirror_scatter(*mirror, wo, hit->normal);
        if (!s) return L;
        rays.add(RayKind::kReflection);
        return L + trace(spawn_ray(*hit, s->wi, offset), RayKind::kReflection, depth + 1,
                         throughput * s->weight, rng, rays);
    }
    if (is_black(brdf)) return L;
    L += throughput * shading_.direct(*hit, wo, rng, rays);
    if (!options_.indirect) return L;
    // The vertex the indirect ray reaches may not bounce again (depth + 1 is the cap), so there it could only
    // add the emission of an emitter light sampling misses: without one, the ray is not worth tracing.
    if (depth + 1 >= options_.termination.max_depth && !indirect_rays_find_emitters_) return L;
    const auto s = uniform_scatter(brdf, wo, hit->normal, rng.next_vec2());
    if (!s) return L;
    rays.add(RayKind::kIndirect);
    return L + trace(spawn_ray(*hit, s->wi, offset), RayKind::kIndirect, depth + 1, throughput * s->weight,
                     rng, rays);
    // END EXERCISE
}

}  // namespace rt
