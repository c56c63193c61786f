// Light from a point light on a diffuse surface, physically scaled. A point light of radiant intensity I
// (W/sr) at distance r sends the flux I dω through a patch of area dA seen at angle θ, dω = cos θ dA / r², so
// the irradiance (W/m²) of the patch is
//     E = I dω / dA                              (Lambert's cosine law and the inverse-square law)
// and a diffuse (Lambertian) surface of albedo ρ reflects the same radiance in every direction:
//     L = (ρ / π) E                              (ρ / π is the Lambert BRDF; chapter 04 derives it)
#pragma once

#include "rt/core/math.hpp"
#include "rt/core/scene.hpp"

namespace rt {

// E at point p with unit normal n, for the light at x (cos θ = n · (x − p) / r, r = |x − p|); zero when the
// light is behind the surface or at the point itself.
Color point_light_irradiance(const PointLight& light, const Vec3& p, const Vec3& n);

// L = (ρ / π) E: the radiance a Lambertian surface of albedo ρ reflects under irradiance E.
inline Color lambert_radiance(const Color& albedo, const Color& irradiance) {
    return albedo * kInvPi * irradiance;
}

}  // namespace rt
