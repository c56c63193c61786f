// Rendering through the pinhole camera, the loop every chapter's picture goes through: sample s of pixel
// (x, y) becomes the camera ray through a point of that pixel (chosen by a pixel sampler), counted as a
// camera ray, and `radiance(ray, rng, rays)` says what that ray sees.
#pragma once

#include "camera.hpp"
#include "pixel_sampling.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

// The ray through film point `film`: the pinhole's, or through a thin lens from the lens point that
// next_lens() draws. A pinhole never calls it, so a scene without a lens draws the numbers it always drew.
template <typename NextLens>
Ray camera_ray_through(const PinholeCamera& camera, Vec2 film, NextLens&& next_lens) {
    if (camera.lens_radius > 0) return thin_lens_ray(camera, film.x, film.y, next_lens());
    return camera_ray(camera, film.x, film.y);
}

// The camera ray of sample `s` (of `count` per pixel) through the point `u` of [0, 1)² places (and the
// lens point next_lens() draws, for a thin lens), counted.
template <typename NextLens>
Ray camera_ray_of(const PinholeCamera& camera, PixelSampler sampler, const PixelSample& s, int count, Vec2 u,
                  NextLens&& next_lens, RayCounts& rays) {
    const Vec2 film = pixel_sample_point(sampler, s.x, s.y, s.index, count, u);
    rays.add(RayKind::kCamera);
    return camera_ray_through(camera, film, next_lens);
}

// The same, u (then the lens point) drawn from `rng`.
inline Ray camera_ray_of(const PinholeCamera& camera, PixelSampler sampler, const PixelSample& s, int count,
                         Pcg32& rng, RayCounts& rays) {
    const Vec2 u = rng.next_vec2();
    return camera_ray_of(
        camera, sampler, s, count, u, [&] { return rng.next_vec2(); }, rays);
}

// A last guard, so no NaN or Inf can reach an image: a non-finite sample is a bug, dropped here rather than
// spread over the pixel; the tests check that none occurs on the course's scenes.
inline Color finite_or_black(const Color& L) {
    return is_finite(L) ? L : Color(0);
}

template <typename Radiance>
RenderResult render_camera_rays(const PinholeCamera& camera, PixelSampler sampler,
                                const RenderSettings& settings, Radiance&& radiance) {
    const int count = settings.samples_per_pixel;
    return render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        return finite_or_black(radiance(camera_ray_of(camera, sampler, s, count, rng, rays), rng, rays));
    });
}

}  // namespace rt
