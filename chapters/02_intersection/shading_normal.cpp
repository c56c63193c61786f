#include "shading_normal.hpp"

#include <algorithm>

namespace rt {

Vec3 shading_normal(const Vec3& interpolated, const Vec3& geometric, const Vec3& wo, ShadingNormalFix fix) {
    if (fix == ShadingNormalFix::kFlat) return geometric;
    // Flip: the vertex normals face outward, the geometric normal faces the viewer (inside or out).
    const Vec3 ns = glm::dot(interpolated, geometric) < 0 ? -interpolated : interpolated;
    if (fix == ShadingNormalFix::kNone) return ns;
    const Real c = glm::dot(wo, ns);
    if (c >= kShadingHorizon) return ns;
    // Bend: ns = c wo + t with t ⊥ wo; keep t's direction and set the wo part to kShadingHorizon,
    // ns' = h wo + sqrt(1 − h²) t / |t|: the smallest rotation toward wo that lifts it above the horizon.
    const Vec3 t = ns - c * wo;
    const Real length = glm::length(t);
    if (!(length > Real(1e-6))) return geometric;  // ns = ±wo: no plane to bend in
    const Real h = kShadingHorizon;
    return glm::normalize(h * wo + std::sqrt(std::max(Real(0), 1 - h * h)) / length * t);
}

}  // namespace rt
