// Light from a point light on a diffuse surface, physically scaled. A point light of radiant intensity I
// (W/sr) at distance r sends the flux I dω through a patch of area dA that subtends the solid angle dω at
// the light, so the patch's irradiance (W/m²) is
//     E = I dω / dA                              (Lambert's cosine law and the inverse-square law)
// and a diffuse (Lambertian) surface of albedo ρ reflects the same radiance L = k ρ E in every direction,
// k the constant for which it sends out over its hemisphere the fraction ρ of what it receives.
#pragma once

#include "rt/core/math.hpp"
#include "rt/core/scene.hpp"

namespace rt {

// E at point p with unit normal n, for the light at x (cos θ = n · (x − p) / r, r = |x − p|); zero when the
// light is behind the surface or at the point itself.
Color point_light_irradiance(const PointLight& light, const Vec3& p, const Vec3& n);

// L = k ρ E: the radiance a Lambertian surface of albedo ρ reflects under irradiance E, per channel, with
// the k for which its exitance ∫ L cos θ dω over the hemisphere is ρ E.
inline Color lambert_radiance(const Color& albedo, const Color& irradiance) {
    // EXERCISE(ch03.lambert_radiance) § Light from a point light
    return albedo * kInvPi * irradiance;
    // END EXERCISE
}

}  // namespace rt
