#include "shadow_ray.hpp"

#include <algorithm>

#include "02_intersection/float_error.hpp"

namespace rt {

namespace {

// The unit ray from `origin` toward `target`, stopping short of it (see spawn_shadow_ray).
ShadowRay segment(const Vec3& origin, const Vec3& target, const Vec3& fallback_direction) {
    const Vec3 to_target = target - origin;
    const Real distance = glm::length(to_target);
    if (!(distance > 0)) return {Ray{origin, fallback_direction}, 0};  // the target is the origin
    const Vec3 direction = to_target / distance;
    // The light's surface is met at t ≈ D, computed from coordinates as large as |target| and |o|: leave out
    // their rounding as well as the relative margin.
    const Real rounding = gamma_bound(8) * glm::dot(abs(direction), abs(target) + abs(origin));
    return {Ray{origin, direction}, std::max(Real(0), (1 - kShadowEpsilon) * distance - rounding)};
}

}  // namespace

ShadowRay spawn_shadow_ray(const Hit& hit, const Vec3& target, const RayOffset& offset) {
    // EXERCISE(ch03.shadow_ray) § The shadow ray
    return segment(offset_origin(hit, target - hit.point, offset), target, hit.normal);
    // END EXERCISE
}

ShadowRay spawn_shadow_ray(const Hit& hit, const SurfacePoint& target, const RayOffset& offset) {
    const Vec3 origin = offset_origin(hit, target.point - hit.point, offset);
    Hit far_end;
    far_end.point = target.point;
    far_end.normal = target.normal;
    far_end.point_error = target.point_error;
    return segment(origin, offset_origin(far_end, origin - target.point, offset), hit.normal);
}

bool visible(const World& world, const Hit& hit, const Vec3& target, const RayOffset& offset,
             RayCounts& rays) {
    const ShadowRay shadow = spawn_shadow_ray(hit, target, offset);
    rays.add(RayKind::kShadow);
    return !world.occluded(shadow.ray, shadow.t_max);
}

bool visible(const World& world, const Hit& hit, const SurfacePoint& target, const RayOffset& offset,
             RayCounts& rays) {
    const ShadowRay shadow = spawn_shadow_ray(hit, target, offset);
    rays.add(RayKind::kShadow);
    return !world.occluded(shadow.ray, shadow.t_max);
}

}  // namespace rt
