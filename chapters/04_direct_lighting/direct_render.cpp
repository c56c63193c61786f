#include "direct_render.hpp"

#include "01_ray_generation/camera_render.hpp"
#include "rt/core/error_metrics.hpp"

namespace rt {

RenderResult render_direct(const DirectLighting& shading, const PinholeCamera& camera,
                           const RenderSettings& settings, FilmPoints film_points) {
    const PixelSampler sampler =
        film_points == FilmPoints::kCentre ? PixelSampler::kCenter : PixelSampler::kStratified;
    return render_camera_rays(camera, sampler, settings, [&](const Ray& ray, Pcg32& rng, RayCounts& rays) {
        return shading.radiance(ray, rng, rays);
    });
}

std::vector<ShadowStudyRow> shadow_study(const World& world, const MaterialTable& materials,
                                         const LightSet& lights, DirectOptions options,
                                         const PinholeCamera& camera, RenderSettings settings,
                                         const Image& exact, const std::vector<LightSampler>& samplers,
                                         const std::vector<int>& shadow_samples) {
    std::vector<ShadowStudyRow> rows;
    settings.samples_per_pixel = 1;
    for (LightSampler sampler : samplers) {
        for (int n : shadow_samples) {
            options.light_sampler = sampler;
            options.shadow_samples = n;
            const DirectLighting shading(world, materials, lights, options);
            const RenderResult r = render_direct(shading, camera, settings, FilmPoints::kCentre);
            const ErrorMetrics e = compare(r.image, exact);
            rows.push_back(
                {sampler, n, e.rmse, e.relative_mse, e.mean_error, r.seconds, r.rays[RayKind::kShadow]});
        }
    }
    return rows;
}

}  // namespace rt
