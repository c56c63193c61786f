// Renders with a path tracer: one path per sample, its numbers from tracer.options().sampler (independent,
// stratified, or Owen-scrambled Sobol, sample_stream.hpp). Any tracer with radiance(ray, stream, rays
// [, observer]) and options() renders here; given an `observer`, each path gets a fresh copy of it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "01_ray_generation/camera.hpp"
#include "01_ray_generation/camera_render.hpp"
#include "owen_sobol.hpp"
#include "rt/render/render_loop.hpp"
#include "sample_stream.hpp"

namespace rt {

template <class Tracer, class Observer = std::nullptr_t>
RenderResult render_paths(const Tracer& tracer, const PinholeCamera& camera, const RenderSettings& settings,
                          const Observer& observer = nullptr) {
    const auto trace = [&](const Ray& ray, SampleStream stream, RayCounts& rays) {
        if constexpr (std::is_null_pointer_v<Observer>) {
            return tracer.radiance(ray, stream, rays);
        } else {
            Observer fresh = observer;
            return tracer.radiance(ray, stream, rays, &fresh);
        }
    };
    const PointSet points = tracer.options().sampler;
    if (points != PointSet::kSobol) {
        return render_camera_rays(
            camera, points == PointSet::kStratified ? PixelSampler::kStratified : PixelSampler::kUniform,
            settings, [&](const Ray& ray, Pcg32& rng, RayCounts& rays) { return trace(ray, rng, rays); });
    }
    // Sobol: the pixel's sequence, point s.index of it; its first two dimensions place the camera ray (the
    // next two its lens point, for a thin lens).
    const int count = settings.samples_per_pixel;
    const auto width = std::uint64_t(settings.width);
    return render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        OwenSobolStream sobol(std::uint64_t(s.y) * width + std::uint64_t(s.x), std::uint32_t(s.index),
                              settings.seed);
        const Vec2 u = sobol.next_vec2();
        const Ray ray = camera_ray_of(
            camera, PixelSampler::kUniform, s, count, u, [&] { return sobol.next_vec2(); }, rays);
        return finite_or_black(trace(ray, SampleStream(sobol, rng), rays));
    });
}

}  // namespace rt
