// Shadow rays: is the segment from a surface point to a point on a light free of occluders? An any-hit query
// (World::occluded) answers it: the first occluder found ends the search, none needs to be the nearest.
#pragma once

#include "02_intersection/hit.hpp"
#include "02_intersection/world.hpp"
#include "ray_offset.hpp"
#include "rt/core/ray.hpp"
#include "rt/core/ray_counts.hpp"

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

// A point sampled on a light's surface: its unit normal (either side) and its rounding bound, per component,
// as a Hit's point_error (for x = Q + a u + b v on a quad, γ₃ (|Q| + |a u| + |b v|); for x = c + r w on a
// sphere, γ₅ (|c| + |r w|)).
struct SurfacePoint {
    Vec3 point{0};
    Vec3 normal{0, 0, 1};
    Vec3 point_error{0};
};
// The segment to a point on a light's surface, both ends offset (PBRT 4's SpawnRayTo): the target x' is x
// moved by the same offset rule toward the origin, so the light's surface lies behind x' at every angle; then
// as above with x' as the target. A bare point cannot do this: a target computed at coordinates of 1e4 lies
// up to ~1e-3 off the light's surface, and a ray meeting that surface at a slant can reach it D · 1e-4 before
// the point.
ShadowRay spawn_shadow_ray(const Hit& hit, const SurfacePoint& target, const RayOffset& offset = {});
bool visible(const World& world, const Hit& hit, const SurfacePoint& target, const RayOffset& offset,
             RayCounts& rays);

}  // namespace rt
