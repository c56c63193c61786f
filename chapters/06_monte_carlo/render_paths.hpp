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

// The radiance `tracer` finds for sample `s` of a pixel (finite, or black), its path told to `observer` if one
// is given: what every render of a path tracer adds per sample, with or without layers beside the image.
// The sample's camera ray and numbers come from tracer.options().sampler: independent or stratified, the
// sample's Pcg32 places the camera ray in the pixel (uniformly or in its stratum) and draws every later
// number; Sobol, the pixel's sequence, point s.index of it: its first pair places the camera ray (the next
// the lens point, for a thin lens), and the sample's Pcg32 stays beside it for code that takes a generator.
template <class Tracer, class ObserverPointer = std::nullptr_t>
Color sample_radiance(const Tracer& tracer, const PinholeCamera& camera, const RenderSettings& settings,
                      const PixelSample& s, Pcg32& rng, RayCounts& rays, ObserverPointer observer = nullptr) {
    const auto trace = [&](const Ray& ray, SampleStream stream) {
        if constexpr (std::is_null_pointer_v<ObserverPointer>) {
            return finite_or_black(tracer.radiance(ray, stream, rays));
        } else {
            return finite_or_black(tracer.radiance(ray, stream, rays, observer));
        }
    };
    const PointSet points = tracer.options().sampler;
    const int count = settings.samples_per_pixel;
    if (points != PointSet::kSobol) {
        const PixelSampler sampler =
            points == PointSet::kStratified ? PixelSampler::kStratified : PixelSampler::kUniform;
        return trace(camera_ray_of(camera, sampler, s, count, rng, rays), SampleStream(rng));
    }
    OwenSobolStream sobol(std::uint64_t(s.y) * std::uint64_t(settings.width) + std::uint64_t(s.x),
                          std::uint32_t(s.index), settings.seed);
    const Vec2 u = sobol.next_vec2();
    const Ray ray = camera_ray_of(
        camera, PixelSampler::kUniform, s, count, u, [&] { return sobol.next_vec2(); }, rays);
    return trace(ray, SampleStream(sobol, rng));
}

template <class Tracer, class Observer = std::nullptr_t>
RenderResult render_paths(const Tracer& tracer, const PinholeCamera& camera, const RenderSettings& settings,
                          const Observer& observer = nullptr) {
    return render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        if constexpr (std::is_null_pointer_v<Observer>) {
            return sample_radiance(tracer, camera, settings, s, rng, rays);
        } else {
            Observer fresh = observer;
            return sample_radiance(tracer, camera, settings, s, rng, rays, &fresh);
        }
    });
}

}  // namespace rt
