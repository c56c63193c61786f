// Snell's law, η_i sin θ_i = η_t sin θ_t, as a direction. wo is unit and points away from the surface; n is a
// unit normal and η = η_t / η_i the ratio of the index on the side opposite wo to the index on wo's side,
// for wo on n's side (n · wo >= 0). The transmitted direction leaves on the other side: wo's part across n
// reversed and scaled by 1 / η (Snell's law), plus the part along −n that makes it unit (cos θ_t, from
// sin² θ_t = sin² θ_i / η²); a unit vector in the plane of wo and n. Entering versus leaving: when wo is on the other side (n · wo < 0)
// the normal and the ratio flip together (n → −n, η → 1 / η), so refract(wo, −n, 1 / η) = refract(wo, n, η).
// Under total internal reflection (cos² θ_t ≤ kTirCos2) there is no wt: the answer is empty, never NaN and
// never a zero vector (glm::refract returns (0, 0, 0) there, which a caller that forgets to check turns into
// a ray with no direction).
#pragma once

#include <optional>

#include "rt/core/math.hpp"

namespace rt {

std::optional<Vec3> refract(const Vec3& wo, const Vec3& n, Real eta);

}  // namespace rt
