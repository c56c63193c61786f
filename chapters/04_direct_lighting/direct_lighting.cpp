#include "direct_lighting.hpp"

#include <algorithm>

#include "01_ray_generation/pixel_sampling.hpp"
#include "03_shadow_rays/shadow_ray.hpp"
#include "frame.hpp"
#include "sampling.hpp"

namespace rt {

DirectLighting::DirectLighting(const World& world, const MaterialTable& materials, LightSet lights,
                               DirectOptions options)
    : world_(world), materials_(materials), lights_(std::move(lights)), options_(options) {
    options_.shadow_samples = std::max(1, options_.shadow_samples);
    const std::size_t count = lights_.lights.size();
    const bool pick = options_.light_selection == LightSelection::kPower ||
                      (options_.light_selection == LightSelection::kAuto && count > kEveryLightLimit);
    if (pick) picker_.emplace(lights_, options_.quad_lights);
}

Color DirectLighting::contribution(const Hit& hit, const Vec3& wo, const Bsdf& brdf, const LightSample& s,
                                   RayCounts& rays) const {
    const Real cos_i = glm::dot(s.wi, hit.shading_normal);
    if (!(cos_i > 0) || !(s.pdf > 0) || is_black(s.radiance)) return Color(0);
    const Color f = eval(brdf, wo, s.wi, hit.shading_normal);
    if (is_black(f)) return Color(0);
    if (options_.simulates(Effect::kShadows)) {
        const bool lit = s.on_surface() ? visible(world_, hit, SurfacePoint{s.point, s.normal, s.point_error},
                                                  options_.offset, rays)
                                        : visible(world_, hit, s.point, options_.offset, rays);
        if (!lit) return Color(0);
    }
    return f * s.radiance * (cos_i / s.pdf);
}

Vec2 DirectLighting::light_point(int j, Pcg32& rng) const {
    const Vec2 u = rng.next_vec2();
    // One sample has one stratum, the whole square: u itself (chapters 07 and 08 take one per vertex).
    if (options_.light_sampler == LightSampler::kIndependent || options_.shadow_samples == 1) return u;
    // Stratum (j mod m, ⌊j / m⌋) of the m × m grid, m = ⌊√N⌋: chapter 01's stratified pixel sample in pixel
    // (0, 0).
    return pixel_sample_point(PixelSampler::kStratified, 0, 0, j, options_.shadow_samples, u);
}

Color DirectLighting::direct(const Hit& hit, const Vec3& wo, Pcg32& rng, RayCounts& rays) const {
    BsdfAtHit at;
    const Bsdf& b = materials_.bsdf(hit, at);
    // A light sample never falls on a delta BRDF's one direction, and a black BRDF reflects nothing: neither
    // needs a single shadow ray.
    if (!options_.simulates(Effect::kDirect) || is_delta(b) || is_black(b)) return Color(0);
    Color sum = picker_ ? picked_lights(hit, wo, b, rng, rays) : every_light(hit, wo, b, rng, rays);
    add_environment(hit, wo, b, rng, rays, sum);
    return sum;
}

Color DirectLighting::every_light(const Hit& hit, const Vec3& wo, const Bsdf& b, Pcg32& rng,
                                  RayCounts& rays) const {
    // EXERCISE(ch04.direct_light) § The BRDF and the direct term
    const int n = options_.shadow_samples;
    const Real weight = Real(1) / Real(n);
    Color sum(0);
    for (const auto& light : lights_.lights) {
        // A delta light has one direction, whose L_e / pdf is all it gives (a point light: I / d²): one
        // sample, no u drawn.
        if (light->is_delta()) {
            if (const auto s = light->sample(hit.point, Vec2(0), options_.quad_lights))
                sum += contribution(hit, wo, b, *s, rays);
            continue;
        }
        for (int j = 0; j < n; ++j) {
            if (const auto s = light->sample(hit.point, light_point(j, rng), options_.quad_lights)) {
                sum += weight * contribution(hit, wo, b, *s, rays);
            }
        }
    }
    return sum;
    // END EXERCISE
}

Color DirectLighting::picked_lights(const Hit& hit, const Vec3& wo, const Bsdf& b, Pcg32& rng,
                                    RayCounts& rays) const {
    const int n = options_.shadow_samples;
    const Real weight = Real(1) / Real(n);
    Color sum(0);
    for (int j = 0; j < n; ++j) {
        const Real u_pick = rng.next_real();
        if (const auto s = picker_->sample(hit.point, u_pick, light_point(j, rng))) {
            sum += weight * contribution(hit, wo, b, *s, rays);
        }
    }
    return sum;
}

void DirectLighting::add_environment(const Hit& hit, const Vec3& wo, const Bsdf& b, Pcg32& rng,
                                     RayCounts& rays, Color& sum) const {
    // The environment: cosine-weighted directions (pdf = cos θ / π); the shadow ray goes to infinity.
    if (!lights_.environment || is_black(lights_.environment->radiance)) return;
    const int n = options_.shadow_samples;
    const Real weight = Real(1) / Real(n);
    const Frame frame = make_frame(hit.shading_normal);
    for (int j = 0; j < n; ++j) {
        const Vec3 wi = glm::normalize(frame.to_world(sample_cosine_hemisphere(light_point(j, rng))));
        const Real cos_i = glm::dot(wi, hit.shading_normal);
        if (!(cos_i > 0)) continue;
        const Color f = eval(b, wo, wi, hit.shading_normal);
        if (is_black(f)) continue;
        if (options_.simulates(Effect::kShadows)) {
            rays.add(RayKind::kShadow);
            if (world_.occluded(spawn_ray(hit, wi, options_.offset), kInfinity)) continue;
        }
        sum += weight * f * lights_.environment->radiance * kPi;  // f L cos / (cos / π)
    }
}

Color DirectLighting::radiance(const Ray& ray, Pcg32& rng, RayCounts& rays) const {
    const auto hit = world_.intersect(ray);
    if (!hit) return lights_.environment ? lights_.environment->radiance : Color(0);
    // Emission is one-sided: the front of a quad (u × v), the outside of a sphere.
    return materials_.emission(hit->material, hit->front_face) + direct(*hit, -ray.direction, rng, rays);
}

}  // namespace rt
