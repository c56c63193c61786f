#include "shadow_ray.hpp"

#include <algorithm>

#include "float_error.hpp"

namespace rt {

ShadowRay spawn_shadow_ray(const Hit& hit, const Vec3& target, const RayOffset& offset) {
    // EXERCISE(ch03.shadow_ray)
    const Vec3 origin = offset_origin(hit, target - hit.point, offset);
    const Vec3 to_target = target - origin;
    const Real distance = glm::length(to_target);
    if (!(distance > 0)) return {Ray{origin, hit.normal}, 0};  // the target is the origin: nothing between
    const Vec3 direction = to_target / distance;
    // The light's surface is met at t ≈ D, computed from coordinates as large as |target| and |o|: leave out
    // their rounding as well as the relative margin.
    const Real rounding = gamma_bound(8) * glm::dot(glm::abs(direction), glm::abs(target) + glm::abs(origin));
    const Real t_max = std::max(Real(0), (1 - kShadowEpsilon) * distance - rounding);
    return {Ray{origin, direction}, t_max};
    // END EXERCISE
}

bool visible(const World& world, const Hit& hit, const Vec3& target, const RayOffset& offset,
             RayCounts& rays) {
    const ShadowRay shadow = spawn_shadow_ray(hit, target, offset);
    rays.add(RayKind::kShadow);
    return !world.occluded(shadow.ray, shadow.t_max);
}

}  // namespace rt
