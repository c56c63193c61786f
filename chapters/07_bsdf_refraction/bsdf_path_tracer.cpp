#include "bsdf_path_tracer.hpp"

#include "brdf.hpp"
#include "camera_render.hpp"
#include "dielectric.hpp"
#include "snell.hpp"

namespace rt {
DirectOptions direct_options(const BsdfPathOptions& o) {
    DirectOptions d;
    d.direct = o.direct;
    d.shadows = o.shadows;
    d.glossy = o.glossy;
    d.offset = o.offset;
    return d;
}

BsdfPathTracer::BsdfPathTracer(const World& world, const Scene& scene, const LightSet& lights,
                               BsdfPathOptions options)
    : world_(world),
      scene_(scene),
      direct_(world, scene, lights, direct_options(options)),
      options_(options),
      environment_(lights.environment) {}

Color BsdfPathTracer::radiance(const Ray& camera_ray, Pcg32& rng, RayCounts& rays) const {
    Color L(0), beta(1);
    Ray ray = camera_ray;
    const bool nee = options_.direct && options_.next_event;
    const bool hits_count = options_.direct && !options_.next_event;
    // Light the path meets counts in full after the camera ray, a mirror or glass bounce, or always without
    // next-event estimation; after a diffuse or glossy bounce next-event estimation already counted it.
    bool delta = true;
    Color absorption(0);  // σ_a of the medium the ray travels in (0: air, or clear glass)
    bool absorbing = false;
    for (int depth = 0;; ++depth) {
        const auto hit = world_.intersect(ray);
        if (absorbing) {
            if (!hit) break;  // an open absorbing shape: nothing comes back from infinitely far inside
            beta *= beer_lambert(absorption, hit->t);
        }
        if (!hit) {
            if (environment_ && (delta || hits_count)) L += beta * environment_->radiance;
            break;
        }
        const Material& material = scene_.materials[std::size_t(hit->material)];
        if (hit->front_face && material.emissive() && (delta || hits_count)) L += beta * material.emission;
        const Vec3 wo = -ray.direction;
        Vec3 wi;
        RayKind kind;
        if (material.type == MaterialType::kDielectric) {
            // hit->normal faces wo already; front_face says which side of the shape that is.
            const Real eta = hit->front_face ? material.ior : 1 / material.ior;
            const DielectricSample s = sample_dielectric(wo, hit->normal, eta, rng.next_real());
            wi = s.wi;
            beta *= s.weight;
            if (s.lobe == DielectricLobe::kTransmission) {
                absorbing = hit->front_face && (material.absorption.r > 0 || material.absorption.g > 0 ||
                                                material.absorption.b > 0);
                absorption = hit->front_face ? material.absorption : Color(0);
                kind = RayKind::kRefraction;
            } else {
                kind = RayKind::kReflection;
            }
            delta = true;
        } else {
            const Brdf& brdf = direct_.brdf(hit->material);
            if (is_black(brdf)) break;
            const bool mirror = is_delta(brdf);
            if (nee && !mirror) L += beta * direct_.direct(*hit, wo, rng, rays);
            // Without the indirect effect a path ends at its first diffuse or glossy vertex.
            if (!mirror && !options_.indirect) break;
            const BrdfSample s = sample(brdf, wo, hit->normal, rng.next_vec2());
            const Real cos_i = glm::dot(s.wi, hit->normal);
            if (!(cos_i > 0) || !(s.pdf > 0)) break;
            wi = s.wi;
            beta *= s.f * (cos_i / s.pdf);
            kind = mirror || !std::holds_alternative<LambertBrdf>(brdf) ? RayKind::kReflection
                                                                        : RayKind::kIndirect;
            delta = mirror;
        }
        if (!continue_path(options_.termination, depth + 1, beta, rng.next_real())) break;
        ray = spawn_ray(*hit, wi, options_.offset);
        rays.add(kind);
    }
    return L;
}

RenderResult render_bsdf_paths(const BsdfPathTracer& tracer, const PinholeCamera& camera,
                               const RenderSettings& settings) {
    return render_camera_rays(
        camera, PixelSampler::kStratified, settings,
        [&](const Ray& ray, Pcg32& rng, RayCounts& rays) { return tracer.radiance(ray, rng, rays); });
}

}  // namespace rt
