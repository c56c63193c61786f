#include "intersection_render.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "01_ray_generation/camera_render.hpp"
#include "01_ray_generation/pixel_sampling.hpp"
#include "rt/render/interrupt.hpp"

namespace rt {

Color normal_colour(const Vec3& n) {
    return (n + Real(1)) * Real(0.5);
}

Color distance_colour(Real t, Real scale) {
    return Color(std::exp(-t / scale));
}

Color heat_colour(Real x) {
    x = std::clamp(x, Real(0), Real(1));
    const Color stops[] = {{0, 0, 0}, {0.1f, 0.1f, 0.8f}, {0.9f, 0.1f, 0.1f}, {1, 0.9f, 0.1f}, {1, 1, 1}};
    const Real s = x * 4;
    const int i = std::min(3, int(s));
    const Real f = s - Real(i);
    return stops[i] * (1 - f) + stops[i + 1] * f;
}

Real cost_heat(std::uint32_t tests) {
    return std::log2(Real(1) + Real(tests)) / 11;
}

RenderResult render_intersections(const World& world, const PinholeCamera& camera, ShowMode mode,
                                  Real distance_scale, const RenderSettings& settings) {
    const int count = settings.samples_per_pixel;
    return render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        const Ray ray = camera_ray_of(camera, PixelSampler::kStratified, s, count, rng, rays);
        if (mode == ShowMode::kCost) {
            TraversalStats stats;
            world.intersect(ray, kInfinity, stats);
            return heat_colour(cost_heat(stats.nodes + stats.primitives));
        }
        const auto hit = world.intersect(ray);
        if (!hit) return Color{0};
        return mode == ShowMode::kNormal ? normal_colour(hit->normal)
                                         : distance_colour(hit->t, distance_scale);
    });
}

std::optional<MeanTraversalCost> mean_traversal_cost(const World& world, const PinholeCamera& camera) {
    std::uint64_t nodes = 0, primitives = 0, rays = 0;
    for (int y = 0; y < camera.height; ++y) {
        for (int x = 0; x < camera.width; ++x) {
            if (interrupt_requested()) return std::nullopt;
            TraversalStats stats;
            world.intersect(camera_ray(camera, Real(x) + Real(0.5), Real(y) + Real(0.5)), kInfinity, stats);
            nodes += stats.nodes;
            primitives += stats.primitives;
            ++rays;
        }
    }
    return MeanTraversalCost{double(nodes) / double(rays), double(primitives) / double(rays)};
}

}  // namespace rt
