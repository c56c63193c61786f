#include "direct_render.hpp"

#include "pixel_sampling.hpp"
#include "rt/error_metrics.hpp"

namespace rt {

RenderResult render_direct(const DirectLighting& shading, const PinholeCamera& camera,
                           const RenderSettings& settings, FilmPoints film_points) {
    const int count = settings.samples_per_pixel;
    const PixelSampler sampler =
        film_points == FilmPoints::kCentre ? PixelSampler::kCenter : PixelSampler::kStratified;
    return render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        const Vec2 film = pixel_sample_point(sampler, s.x, s.y, s.index, count, rng.next_vec2());
        const Ray ray = camera_ray(camera, film.x, film.y);
        rays.add(RayKind::kCamera);
        const Color L = shading.radiance(ray, rng, rays);
        // A last guard, so no NaN or Inf can reach an image; the tests check that none occurs on the course's
        // scenes.
        return is_finite(L) ? L : Color(0);
    });
}

std::vector<ShadowStudyRow> shadow_study(const World& world, const Scene& scene, const LightSet& lights,
                                         DirectOptions options, const PinholeCamera& camera,
                                         RenderSettings settings, const Image& exact,
                                         const std::vector<LightSampler>& samplers,
                                         const std::vector<int>& shadow_samples) {
    std::vector<ShadowStudyRow> rows;
    settings.samples_per_pixel = 1;
    for (LightSampler sampler : samplers) {
        for (int n : shadow_samples) {
            options.light_sampler = sampler;
            options.shadow_samples = n;
            const DirectLighting shading(world, scene, lights, options);
            const RenderResult r = render_direct(shading, camera, settings, FilmPoints::kCentre);
            const ErrorMetrics e = compare(r.image, exact);
            rows.push_back(
                {sampler, n, e.rmse, e.relative_mse, e.mean_error, r.seconds, r.rays[RayKind::kShadow]});
        }
    }
    return rows;
}

}  // namespace rt
