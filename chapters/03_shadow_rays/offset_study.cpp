#include "offset_study.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>

#include "02_intersection/world.hpp"
#include "exact_visibility.hpp"
#include "point_light.hpp"
#include "scene_scale.hpp"
#include "shadow_ray.hpp"
#include "shadow_render.hpp"
#include "rt/core/median.hpp"

namespace rt {
namespace {

enum : unsigned char { kAcne = 1, kLeak = 2 };

// Traces every camera sample's shadow rays once more and judges each against the exact visibility.
void judge(const World& world, const Scene& scene, const ExactVisibility& exact, const PinholeCamera& camera,
           const RayOffset& offset, RenderSettings settings, OffsetStudyRow& row) {
    const std::size_t pixels = std::size_t(settings.width) * std::size_t(settings.height);
    const auto flags = std::make_unique<std::atomic<unsigned char>[]>(pixels);
    std::atomic<std::uint64_t> self_hits{0};
    const int spp = settings.samples_per_pixel;
    settings.progress = ProgressStyle::kNone;
    render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        const auto hit = world.intersect(primary_ray(camera, s, spp, rng));
        if (!hit) return Color(0);
        unsigned char flag = 0;
        for (const PointLight& light : scene.point_lights) {
            if (point_light_irradiance(light, hit->point, hit->normal) == Color(0)) continue;
            const ShadowRay shadow = spawn_shadow_ray(*hit, light.position, offset);
            rays.add(RayKind::kShadow);
            const auto first = world.intersect(shadow.ray, shadow.t_max);
            if (first && first->primitive == hit->primitive)
                self_hits.fetch_add(1, std::memory_order_relaxed);
            const bool truly_visible =
                exact.visible(hit->primitive, Vec3d(hit->point), Vec3d(light.position));
            if (first && truly_visible) flag |= kAcne;
            if (!first && !truly_visible) flag |= kLeak;
        }
        const std::size_t pixel = std::size_t(s.y) * std::size_t(settings.width) + std::size_t(s.x);
        flags[pixel].fetch_or(flag, std::memory_order_relaxed);
        return Color(0);
    });
    row.self_hits = self_hits.load();
    for (std::size_t i = 0; i < pixels; ++i) {
        const unsigned char f = flags[i].load();
        row.acne_pixels += (f & kAcne) ? 1 : 0;
        row.leak_pixels += (f & kLeak) ? 1 : 0;
    }
}

// The shadow rays' starting hits and targets at every pixel centre.
std::vector<std::pair<Hit, Vec3>> shadow_queries(const World& world, const Scene& scene,
                                                 const PinholeCamera& camera) {
    std::vector<std::pair<Hit, Vec3>> queries;
    for (int y = 0; y < camera.height; ++y) {
        for (int x = 0; x < camera.width; ++x) {
            const auto hit = world.intersect(camera_ray(camera, Real(x) + Real(0.5), Real(y) + Real(0.5)));
            if (!hit) continue;
            for (const PointLight& light : scene.point_lights) {
                if (point_light_irradiance(light, hit->point, hit->normal) != Color(0))
                    queries.emplace_back(*hit, light.position);
            }
        }
    }
    return queries;
}

// ns per offset_origin call (the method's own work: the origin of one shadow ray), over the queries for at
// least 10 ms.
double time_offset(const std::vector<std::pair<Hit, Vec3>>& queries, const RayOffset& offset) {
    if (queries.empty()) return 0;
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    std::uint64_t calls = 0;
    Vec3 sink{0};
    do {
        for (const auto& [hit, target] : queries) sink += offset_origin(hit, target - hit.point, offset);
        calls += queries.size();
    } while (Clock::now() - start < std::chrono::milliseconds(10));
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    volatile Real keep = sink.x + sink.y + sink.z;  // the loop's result is used, so it is not optimised away
    (void)keep;
    return seconds * 1e9 / double(calls);
}

}  // namespace

std::vector<OffsetStudyRow> offset_study(const Scene& scene, const std::vector<Real>& scales,
                                         const std::vector<RayOffset>& methods,
                                         const RenderSettings& settings) {
    std::vector<OffsetStudyRow> rows;
    for (Real scale : scales) {
        const Scene scaled = scale_scene(scene, scale);
        const World world(scaled);
        const ExactVisibility exact(scaled);
        const PinholeCamera camera = make_pinhole_camera(scaled.camera, settings.width, settings.height);
        const auto queries = shadow_queries(world, scaled, camera);
        // The methods take turns, round after round, so a burst of load on this shared machine falls on all
        // of them alike; each time is the median of its rounds (3 renders, 7 offset timings).
        const std::size_t first = rows.size();
        for (const RayOffset& offset : methods) {
            OffsetStudyRow row;
            row.scale = scale;
            row.offset = offset;
            rows.push_back(row);
        }
        RenderSettings quiet = settings;
        quiet.progress = ProgressStyle::kNone;
        std::vector<std::vector<double>> render_seconds(methods.size()), offset_ns(methods.size());
        for (int round = 0; round < 7; ++round) {
            for (std::size_t m = 0; m < methods.size(); ++m) {
                OffsetStudyRow& row = rows[first + m];
                if (round < 3) {
                    const RenderResult r =
                        render_shadows(world, scaled, camera, ShadowOptions{methods[m], true, true}, quiet);
                    render_seconds[m].push_back(r.seconds);
                    row.shadow_rays = r.rays[RayKind::kShadow];
                    row.mean = r.image.mean();
                }
                offset_ns[m].push_back(time_offset(queries, methods[m]));
            }
        }
        for (std::size_t m = 0; m < methods.size(); ++m) {
            OffsetStudyRow& row = rows[first + m];
            row.seconds = median(render_seconds[m]);
            row.offset_ns = median(offset_ns[m]);
            judge(world, scaled, exact, camera, methods[m], settings, row);
        }
    }
    return rows;
}

}  // namespace rt
