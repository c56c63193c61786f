#include "ray_offset.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "next_float.hpp"
#include "rt/core/errors.hpp"

namespace rt {

RayOffset make_ray_offset(OffsetMethod method, Real epsilon) {
    if (!(epsilon > 0 && std::isfinite(epsilon))) {
        char text[64];
        std::snprintf(text, sizeof text, "%g", double(epsilon));
        throw InputError(std::string("--epsilon: must be a finite number > 0, got ") + text);
    }
    return {method, epsilon};
}

Vec3 robust_offset(const Vec3& p, const Vec3& point_error, const Vec3& n, const Vec3& direction) {
    // EXERCISE(ch03.robust_offset) § Leaving a surface: shadow acne
    const Real delta = glm::dot(abs(n), point_error);  // δ = |n| · e
    Vec3 offset = delta * n;
    if (glm::dot(direction, n) < 0) offset = -offset;
    Vec3 origin = p + offset;
    // p + offset is rounded too, possibly back toward the surface: one more ulp outward covers that.
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0) origin[i] = next_float_up(origin[i]);
        if (offset[i] < 0) origin[i] = next_float_down(origin[i]);
    }
    return origin;
    // END EXERCISE
}

Vec3 epsilon_offset(const Vec3& p, const Vec3& n, const Vec3& direction, Real epsilon) {
    return glm::dot(direction, n) < 0 ? p - epsilon * n : p + epsilon * n;
}

Vec3 offset_origin(const Hit& hit, const Vec3& direction, const RayOffset& offset) {
    switch (offset.method) {
        case OffsetMethod::kNone:
            return hit.point;
        case OffsetMethod::kEpsilon:
            return epsilon_offset(hit.point, hit.normal, direction, offset.epsilon);
        case OffsetMethod::kRobust:
            return robust_offset(hit.point, hit.point_error, hit.normal, direction);
    }
    return hit.point;
}

Ray spawn_ray(const Hit& hit, const Vec3& direction, const RayOffset& offset) {
    return Ray{offset_origin(hit, direction, offset), direction};
}

}  // namespace rt
