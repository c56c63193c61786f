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

// Sample `s`'s camera ray and number stream as `points` makes them, handed to trace(ray, stream, rays):
// independent or stratified, the sample's Pcg32 places the camera ray in the pixel (uniformly or in its
// stratum) and draws every later number; Sobol, the pixel's sequence, point s.index of it: its first pair
// places the camera ray (the next the lens point, for a thin lens), and the sample's Pcg32 stays beside it
// for code that takes a generator. What every render of a path tracer does per sample, with or without
// extra layers.
template <class Trace>
auto trace_camera_sample(PointSet points, const PinholeCamera& camera, const RenderSettings& settings,
                         const PixelSample& s, Pcg32& rng, RayCounts& rays, Trace&& trace) {
    const int count = settings.samples_per_pixel;
    if (points != PointSet::kSobol) {
        const PixelSampler sampler =
            points == PointSet::kStratified ? PixelSampler::kStratified : PixelSampler::kUniform;
        return trace(camera_ray_of(camera, sampler, s, count, rng, rays), SampleStream(rng), rays);
    }
    OwenSobolStream sobol(std::uint64_t(s.y) * std::uint64_t(settings.width) + std::uint64_t(s.x),
                          std::uint32_t(s.index), settings.seed);
    const Vec2 u = sobol.next_vec2();
    const Ray ray = camera_ray_of(
        camera, PixelSampler::kUniform, s, count, u, [&] { return sobol.next_vec2(); }, rays);
    return trace(ray, SampleStream(sobol, rng), rays);
}

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
    return render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        return finite_or_black(
            trace_camera_sample(tracer.options().sampler, camera, settings, s, rng, rays, trace));
    });
}

}  // namespace rt
