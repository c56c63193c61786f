#include "intersection_render.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

#include "pixel_sampling.hpp"
#include "rt/errors.hpp"

namespace rt {

ShowMode show_mode_from_string(std::string_view name) {
    if (name == "normal") return ShowMode::kNormal;
    if (name == "distance") return ShowMode::kDistance;
    if (name == "cost") return ShowMode::kCost;
    throw InputError("--show: expected normal, distance or cost, got " + std::string(name));
}

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

IntersectionRender render_intersections(const World& world, const PinholeCamera& camera, ShowMode mode,
                                        Real distance_scale, const RenderSettings& settings) {
    std::atomic<std::uint64_t> tests{0};
    const int count = settings.samples_per_pixel;
    IntersectionRender out;
    out.result = render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        const Vec2 film =
            pixel_sample_point(PixelSampler::kStratified, s.x, s.y, s.index, count, rng.next_vec2());
        const Ray ray = camera_ray(camera, film.x, film.y);
        rays.add(RayKind::kCamera);
        TraversalStats stats;
        const auto hit = world.intersect(ray, kInfinity, stats);
        tests.fetch_add(stats.nodes + stats.primitives, std::memory_order_relaxed);
        switch (mode) {
            case ShowMode::kNormal:
                return hit ? normal_colour(hit->normal) : Color{0};
            case ShowMode::kDistance:
                return hit ? distance_colour(hit->t, distance_scale) : Color{0};
            case ShowMode::kCost:
                return heat_colour(cost_heat(stats.nodes + stats.primitives));
        }
        return Color{0};
    });
    const std::uint64_t camera_rays = out.result.rays[RayKind::kCamera];
    out.mean_tests = camera_rays > 0 ? double(tests.load()) / double(camera_rays) : 0.0;
    return out;
}

}  // namespace rt
