#include "scatter.hpp"

#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/sampling.hpp"

namespace rt {
std::optional<Scatter> mirror_scatter(const MirrorBrdf& mirror, const Vec3& wo, const Vec3& n) {
    // EXERCISE(ch05.mirror_scatter) § The rendering equation, as a recursion
    if (is_black(mirror.reflectance)) return std::nullopt;
    const Vec3 r = reflect(wo, n);
    const Real length = glm::length(r);
    if (!(length > 0)) return std::nullopt;
    const Vec3 wi = r / length;
    if (!(glm::dot(wi, n) > 0)) return std::nullopt;  // grazing: the reflection would run along the surface
    return Scatter{wi, mirror.reflectance};
    // END EXERCISE
}

std::optional<Scatter> uniform_scatter(const Bsdf& brdf, const Vec3& wo, const Vec3& n, Vec2 u) {
    // EXERCISE(ch05.uniform_scatter) § The rendering equation, as a recursion
    const Vec3 wi = glm::normalize(make_frame(n).to_world(sample_uniform_hemisphere(u)));
    const Real cos_i = glm::dot(wi, n);
    if (!(cos_i > 0)) return std::nullopt;
    const Color f = eval(brdf, wo, wi, n);
    if (is_black(f)) return std::nullopt;
    return Scatter{wi, f * (cos_i / kUniformHemispherePdf)};
    // END EXERCISE
}

}  // namespace rt
