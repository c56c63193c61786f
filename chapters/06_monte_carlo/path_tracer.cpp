#include "path_tracer.hpp"

#include <algorithm>

#include "camera_render.hpp"
#include "frame.hpp"
#include "mis.hpp"
#include "sampling.hpp"
#include "shadow_ray.hpp"
#include "warp_pdfs.hpp"

namespace rt {
PathTracer::PathTracer(const World& world, const Scene& scene, const LightSet& lights, PathOptions options)
    : world_(world),
      scene_(scene),
      picker_(lights),
      points_(lights.points),
      environment_(lights.environment),
      options_(options) {
    if (environment_ && is_black(environment_->radiance)) environment_.reset();
    // The World numbers its planes after every bounded primitive.
    std::size_t planes = 0;
    for (const Shape& shape : scene.shapes)
        planes += std::holds_alternative<PlaneShape>(shape.geometry) ? 1 : 0;
    bounded_primitives_ = std::uint32_t(world.primitive_count() - planes);
    const Brdf stand_in = LambertBrdf{options_.dielectric_albedo};
    for (const Material& m : scene.materials) {
        const Brdf b = options_.glossy ? brdf_of(m, stand_in) : without_lobes(brdf_of(m, stand_in));
        brdfs_.push_back(b);
        black_.push_back(is_black(b) ? 1 : 0);
        delta_.push_back(is_delta(b) ? 1 : 0);
    }
}

Real PathTracer::brdf_pdf(const Brdf& brdf, const Vec3& wo, const Vec3& wi, const Vec3& n) const {
    return pdf(brdf, wo, wi, n);
}

Color PathTracer::next_event(const Hit& hit, const Vec3& wo, const Brdf& brdf, Pcg32& rng,
                             RayCounts& rays) const {
    const bool mis = options_.strategy == SamplingStrategy::kMis;
    const Vec3& n = hit.normal;
    Color sum(0);
    if (!picker_.empty()) {
        const Real u_pick = rng.next_real();
        const Vec2 u = rng.next_vec2();
        if (const auto s = picker_.sample(hit.point, u_pick, u)) {
            const Real cos_i = glm::dot(s->wi, n);
            if (cos_i > 0 && s->pdf > 0) {
                const Color f = eval(brdf, wo, s->wi, n);
                if (!is_black(f) &&
                    (!options_.shadows || visible(world_, hit, s->point, options_.offset, rays))) {
                    const Real w = mis ? power_heuristic(s->pdf, brdf_pdf(brdf, wo, s->wi, n)) : Real(1);
                    sum += f * s->radiance * (cos_i * w / s->pdf);
                }
            }
        }
    }
    if (environment_) {
        // The uniform environment is sampled like chapter 04's: cosine-weighted, pdf = cos θ / π.
        const Vec3 wi = glm::normalize(make_frame(n).to_world(sample_cosine_hemisphere(rng.next_vec2())));
        const Real cos_i = glm::dot(wi, n);
        const Color f = cos_i > 0 ? eval(brdf, wo, wi, n) : Color(0);
        if (!is_black(f)) {
            bool seen = true;
            if (options_.shadows) {
                rays.add(RayKind::kShadow);
                seen = !world_.occluded(spawn_ray(hit, wi, options_.offset), kInfinity);
            }
            if (seen) {
                const Real pdf_env = cos_i * kInvPi;
                const Real w = mis ? power_heuristic(pdf_env, brdf_pdf(brdf, wo, wi, n)) : Real(1);
                sum += f * environment_->radiance * (cos_i * w / pdf_env);
            }
        }
    }
    // A point light is a delta: no BRDF sample can hit it, so its light sample has weight 1.
    for (const PointLight& light : points_) {
        const Vec3 to_light = light.position - hit.point;
        const Real d2 = glm::dot(to_light, to_light);
        if (!(d2 > 0)) continue;
        const Vec3 wi = to_light / std::sqrt(d2);
        const Real cos_i = glm::dot(wi, n);
        if (!(cos_i > 0)) continue;
        const Color f = eval(brdf, wo, wi, n);
        if (is_black(f)) continue;
        if (options_.shadows && !visible(world_, hit, light.position, options_.offset, rays)) continue;
        sum += f * light.intensity * (cos_i / d2);
    }
    return sum;
}

Color PathTracer::radiance(const Ray& camera_ray, Pcg32& rng, RayCounts& rays) const {
    // EXERCISE(ch06.path_tracer)
    const SamplingStrategy strategy = options_.strategy;
    const bool nee = options_.direct && samples_lights(strategy);
    const bool mis = strategy == SamplingStrategy::kMis;
    Color L(0), beta(1);
    Ray ray = camera_ray;
    bool specular = true;   // the camera ray, or a mirror bounce: what it hits counts in full
    Real previous_pdf = 0;  // the BRDF-sampling density of the ray's direction, for MIS
    Vec3 previous_point(0), previous_normal(0);
    int bounces = 0;  // diffuse and glossy bounces so far
    for (int depth = 0;; ++depth) {
        const auto hit = world_.intersect(ray);
        // Light the path meets: counted in full without next-event estimation, weighted by MIS with it, and
        // not at all by the light strategy (its next-event estimate already counted it).
        if (!hit) {
            if (environment_ && (specular || options_.direct)) {
                Real w = 1;
                if (!specular && nee) {
                    const Real pdf_light =
                        std::max(Real(0), glm::dot(ray.direction, previous_normal)) * kInvPi;
                    w = mis ? power_heuristic(previous_pdf, pdf_light) : Real(0);
                }
                L += beta * environment_->radiance * w;
            }
            break;
        }
        const Material& material = scene_.materials[std::size_t(hit->material)];
        if (hit->front_face && material.emissive() && (specular || options_.direct)) {
            Real w = 1;
            // An emissive plane is not among the lights next-event estimation samples (it has no finite
            // area): only a path that hits it sees it, whatever the strategy.
            const bool sampled = hit->primitive < bounded_primitives_;
            if (!specular && nee && sampled) {
                w = mis ? power_heuristic(previous_pdf,
                                          picker_.pdf(previous_point, ray.direction, *hit, material.emission))
                        : Real(0);
            }
            L += beta * material.emission * w;
        }
        if (!options_.indirect && bounces >= 1) break;
        const std::size_t m = std::size_t(hit->material);
        if (black_[m]) break;
        const Brdf& brdf = brdfs_[m];
        const bool delta = delta_[m] != 0;
        const Vec3 wo = -ray.direction;
        const Vec3& n = hit->normal;
        if (nee && !delta) L += beta * next_event(*hit, wo, brdf, rng, rays);

        // The direction that continues the path, and its density.
        Vec3 wi;
        Color f;
        Real pdf;
        const Vec2 u = rng.next_vec2();
        if (delta || strategy == SamplingStrategy::kBrdf || nee) {
            const BrdfSample s = sample(brdf, wo, n, u);
            wi = s.wi;
            f = s.f;
            pdf = s.pdf;
        } else {
            const bool uniform = strategy == SamplingStrategy::kUniform;
            const Vec3 local = uniform ? sample_uniform_hemisphere(u) : sample_cosine_hemisphere(u);
            wi = glm::normalize(make_frame(n).to_world(local));
            pdf = uniform ? uniform_hemisphere_pdf(local) : cosine_hemisphere_pdf(local);
            f = eval(brdf, wo, wi, n);
        }
        const Real cos_i = glm::dot(wi, n);
        if (!(cos_i > 0) || !(pdf > 0) || is_black(f)) break;
        beta *= f * (cos_i / pdf);
        if (!delta) ++bounces;
        specular = delta;
        previous_pdf = delta ? kInfinity : pdf;
        previous_point = hit->point;
        previous_normal = n;
        if (!continue_path(options_.termination, depth + 1, beta, rng.next_real())) break;
        ray = spawn_ray(*hit, wi, options_.offset);
        rays.add(std::holds_alternative<LambertBrdf>(brdf) ? RayKind::kIndirect : RayKind::kReflection);
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
