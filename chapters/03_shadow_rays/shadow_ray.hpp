// Shadow rays: is the segment from a surface point to a point on a light free of occluders? An any-hit query
// (World::occluded) answers it: the first occluder found ends the search, none needs to be the nearest.
#pragma once

#include "hit.hpp"
#include "ray_offset.hpp"
#include "rt/ray.hpp"
#include "rt/ray_counts.hpp"
#include "world.hpp"

namespace rt {

// The fraction of the distance to the target that a shadow ray leaves out (PBRT's ShadowEpsilon).
inline constexpr Real kShadowEpsilon = Real(1e-4);

// The segment from the surface point `hit` to `target` (a point on a light): a unit-direction ray and the
// t_max at which it stops just before the target, so the light's own surface never occludes itself. o =
// offset_origin(hit, target − p), D = |target − o|, d = (target − o) / D, t_max = (1 − kShadowEpsilon) D − γ₈
// (|d| · (|target| + |o|))  (the rounding of the light's own hit, clamped ≥ 0).
struct ShadowRay {
    Ray ray;
    Real t_max;
};
ShadowRay spawn_shadow_ray(const Hit& hit, const Vec3& target, const RayOffset& offset = {});

// Whether `target` is visible from `hit` (an any-hit query); counts one shadow ray into `rays`.
bool visible(const World& world, const Hit& hit, const Vec3& target, const RayOffset& offset,
             RayCounts& rays);

}  // namespace rt
