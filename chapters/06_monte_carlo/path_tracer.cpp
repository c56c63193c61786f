#include "path_tracer.hpp"

#include <algorithm>
#include <cmath>

#include "01_ray_generation/camera_render.hpp"
#include "03_shadow_rays/shadow_ray.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "mis.hpp"
#include "warp_pdfs.hpp"

namespace rt {
PathTracer::PathTracer(const World& world, const MaterialTable& materials, const LightSet& lights,
                       PathOptions options)
    : world_(world),
      materials_(materials),
      picker_(lights),
      environment_(lights.environment),
      has_unsampled_emitters_(!lights.unsampled.empty()),
      options_(options) {
    if (environment_ && is_black(environment_->radiance)) environment_.reset();
}

Color PathTracer::next_event(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, Pcg32& rng,
                             RayCounts& rays) const {
    const bool mis = options_.strategy == SamplingStrategy::kMis;
    const bool shadows = options_.simulates(Effect::kShadows);
    // A BSDF that transmits is lit from both sides; |cos θ_i| then weighs light from behind the surface.
    const bool both_sides = bsdf.flags().transmission;
    const Vec3& n = hit.normal;
    Color sum(0);
    if (!picker_.empty()) {
        const Real u_pick = rng.next_real();
        const Vec2 u = rng.next_vec2();
        if (const auto s = picker_.sample(hit.point, u_pick, u)) {
            const Real dot_i = glm::dot(s->wi, n);
            const Real cos_i = both_sides ? std::abs(dot_i) : dot_i;
            if (cos_i > 0 && s->pdf > 0) {
                const Color f = bsdf.eval(wo, s->wi, n);
                if (!is_black(f) && (!shadows || visible(world_, hit, s->point, options_.offset, rays))) {
                    // A point light is a delta: no BSDF sample can hit it, so its light sample has weight 1.
                    const Real w =
                        mis && s->on_surface() ? power_heuristic(s->pdf, bsdf.pdf(wo, s->wi, n)) : Real(1);
                    sum += f * s->radiance * (cos_i * w / s->pdf);
                }
            }
        }
    }
    if (environment_) {
        // The uniform environment is sampled like chapter 04's: cosine-weighted, pdf = cos θ / π.
        const Vec3 wi = glm::normalize(make_frame(n).to_world(sample_cosine_hemisphere(rng.next_vec2())));
        const Real cos_i = glm::dot(wi, n);
        const Color f = cos_i > 0 ? bsdf.eval(wo, wi, n) : Color(0);
        if (!is_black(f)) {
            bool seen = true;
            if (shadows) {
                rays.add(RayKind::kShadow);
                seen = !world_.occluded(spawn_ray(hit, wi, options_.offset), kInfinity);
            }
            if (seen) {
                const Real pdf_env = cosine_hemisphere_pdf(cos_i);
                const Real w = mis ? power_heuristic(pdf_env, bsdf.pdf(wo, wi, n)) : Real(1);
                sum += f * environment_->radiance * (cos_i * w / pdf_env);
            }
        }
    }
    return sum;
}

Color PathTracer::radiance(const Ray& camera_ray, Pcg32& rng, RayCounts& rays, PathFeatures* features) const {
    // EXERCISE(ch06.path_tracer)
    const SamplingStrategy strategy = options_.strategy;
    const bool direct = options_.simulates(Effect::kDirect);
    const bool indirect = options_.simulates(Effect::kIndirect);
    const bool nee = direct && samples_lights(strategy);
    const bool mis = strategy == SamplingStrategy::kMis;
    Color L(0), beta(1);
    Ray ray = camera_ray;
    bool specular = true;   // the camera ray, or a delta bounce: what it hits counts in full
    Real previous_pdf = 0;  // the BSDF-sampling density of the ray's direction, for MIS
    Vec3 previous_point(0), previous_normal(0);
    int bounces = 0;  // non-delta bounces so far
    Real length = 0;  // of the path so far, for `features`
    for (int depth = 0;; ++depth) {
        const auto hit = world_.intersect(ray);
        // Light the path meets: counted in full without next-event estimation, weighted by MIS with it, and
        // not at all by the light strategy (its next-event estimate already counted it).
        if (!hit) {
            if (environment_ && (specular || direct)) {
                Real w = 1;
                if (!specular && nee) {
                    const Real pdf_light = cosine_hemisphere_pdf(glm::dot(ray.direction, previous_normal));
                    w = mis ? power_heuristic(previous_pdf, pdf_light) : Real(0);
                }
                L += beta * environment_->radiance * w;
            }
            break;
        }
        // A segment that ends on the inside of a shape ran through what fills it.
        if (!hit->front_face) {
            if (const Medium* medium = materials_.interior(hit->material))
                beta *= medium->transmittance(hit->t);
        }
        const Color emitted = materials_.emission(hit->material, hit->front_face);
        if (!is_black(emitted) && (specular || direct)) {
            Real w = 1;
            // The hit knows its light. An emissive plane is none (Hit::light = −1): next-event estimation
            // cannot sample it (no finite area), so only a path that hits it sees it, whatever the strategy.
            if (!specular && nee && hit->light >= 0) {
                w = mis ? power_heuristic(previous_pdf, picker_.pdf(previous_point, ray.direction, *hit))
                        : Real(0);
            }
            L += beta * emitted * w;
        }
        if (!indirect && bounces >= 1) break;
        const Bsdf& bsdf = materials_.bsdf(hit->material, hit->front_face);
        const BsdfFlags& flags = bsdf.flags();
        length += hit->t;
        const bool records = features && !features->recorded && !flags.delta;
        // Chapter 10's features, at the first vertex that is not a delta bounce (the albedo once the bounce
        // is drawn).
        if (records) *features = {Color(0), hit->normal, length, true};
        if (flags.black) break;
        const Vec3 wo = -ray.direction;
        const Vec3& n = hit->normal;
        if (nee && !flags.delta) L += beta * next_event(*hit, wo, bsdf, rng, rays);
        // Without the indirect effect the path ends at the vertex it reaches next, where light sampling alone
        // (no MIS) already counted every light it could meet — unless some emitter cannot be sampled.
        if (!indirect && !flags.delta && nee && !mis && !has_unsampled_emitters_) break;

        // The direction that continues the path, and its density.
        BsdfSample s;
        const Vec2 u = rng.next_vec2();
        if (flags.delta || strategy == SamplingStrategy::kBrdf || nee) {
            // A BSDF with two lobes (reflection and transmission) takes one more number to choose between
            // them.
            s = bsdf.sample(wo, n, u, flags.transmission ? rng.next_real() : Real(0));
        } else {
            const bool uniform = strategy == SamplingStrategy::kUniform;
            const Vec3 local = uniform ? sample_uniform_hemisphere(u) : sample_cosine_hemisphere(u);
            s.wi = glm::normalize(make_frame(n).to_world(local));
            s.pdf = uniform ? uniform_hemisphere_pdf(local) : cosine_hemisphere_pdf(local.z);
            s.f = bsdf.eval(wo, s.wi, n);
        }
        const Real cos_i = scattering_cosine(s.wi, n, s.transmitted);
        if (!(cos_i > 0) || !(s.pdf > 0) || is_black(s.f)) break;
        if (records) features->albedo = beta * s.f * (cos_i / s.pdf);
        beta *= s.f * (cos_i / s.pdf);
        if (!flags.delta) ++bounces;
        specular = flags.delta;
        previous_pdf = flags.delta ? kInfinity : s.pdf;
        previous_point = hit->point;
        previous_normal = n;
        if (!continue_path(options_.termination, depth + 1, beta, rng.next_real())) break;
        ray = spawn_ray(*hit, s.wi, options_.offset);
        rays.add(ray_kind(flags, s.transmitted));
    }
    return L;
    // END EXERCISE
}

RenderResult render_paths(const PathTracer& tracer, const PinholeCamera& camera,
                          const RenderSettings& settings) {
    return render_camera_rays(
        camera, PixelSampler::kStratified, settings,
        [&](const Ray& ray, Pcg32& rng, RayCounts& rays) { return tracer.radiance(ray, rng, rays); });
}

}  // namespace rt
