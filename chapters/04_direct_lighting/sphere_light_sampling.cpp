#include "sphere_light_sampling.hpp"

#include <algorithm>
#include <cmath>

#include "02_intersection/float_error.hpp"
#include "frame.hpp"
#include "sampling.hpp"

namespace rt {
namespace {

struct Cone {
    Vec3 axis;      // unit, from p to the centre
    Real distance;  // d
    Real sin2_max;  // (r / d)²
};

std::optional<Cone> cone_of(const SphereLight& light, const Vec3& p) {
    const Vec3 to_centre = light.center - p;
    const Real d = glm::length(to_centre);
    if (!(d > light.radius)) return std::nullopt;
    const Real ratio = light.radius / d;  // (r / d)² rather than r² / d², which overflows far away
    return Cone{to_centre / d, d, ratio * ratio};
}

}  // namespace

Real one_minus_cos_stable(Real sin2_max) {
    // EXERCISE(ch04.cone_solid_angle) § Sampling the lights
    const Real cos_max = std::sqrt(std::max(Real(0), 1 - sin2_max));
    return sin2_max / (1 + cos_max);
    // END EXERCISE
}

Real one_minus_cos_naive(Real sin2_max) {
    return 1 - std::sqrt(std::max(Real(0), 1 - sin2_max));
}

Real sphere_light_pdf(const SphereLight& light, const Vec3& p) {
    const auto cone = cone_of(light, p);
    return cone ? Real(1) / (2 * kPi * one_minus_cos_stable(cone->sin2_max)) : Real(0);
}

std::optional<LightSample> sample_sphere_light(const SphereLight& light, const Vec3& p, Vec2 u) {
    const auto cone = cone_of(light, p);
    if (!cone) return std::nullopt;
    const Real one_minus_cos_max = one_minus_cos_stable(cone->sin2_max);
    const Vec3 local = sample_uniform_cone(u, one_minus_cos_max);
    const Vec3 wi = glm::normalize(make_frame(cone->axis).to_world(local));
    // The near root of |p + t wi − c| = r: t = (d² − r²) / (d cos θ + √(r² − d² sin² θ)), the product of the
    // roots divided by the far one, so a point p close to the sphere does not cancel.
    const Real d = cone->distance, r = light.radius;
    const Real cos_theta = std::min(Real(1), local.z);
    const Real d_sin = d * std::sqrt(local.x * local.x + local.y * local.y);  // not √(1 − cos²θ): it cancels
    const Real root = std::sqrt(std::max(Real(0), (r - d_sin) * (r + d_sin)));
    const Real t = (d - r) * (d + r) / (d * cos_theta + root);
    const Real pdf = Real(1) / (2 * kPi * one_minus_cos_max);
    // The point pushed back onto the sphere, x = c + r w (chapter 02's reprojection), with its rounding
    // bound.
    const Vec3 w = glm::normalize(p + t * wi - light.center);
    const Vec3 radial = light.radius * w;
    const Vec3 error = gamma_bound(5) * (abs(light.center) + abs(radial));
    return LightSample{light.center + radial, wi, t, light.radiance, pdf, w, error};
}

}  // namespace rt
