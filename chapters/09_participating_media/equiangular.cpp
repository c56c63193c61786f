#include "equiangular.hpp"

#include <algorithm>
#include <cmath>

#include "03_shadow_rays/next_float.hpp"

namespace rt {

std::optional<EquiangularSampler> EquiangularSampler::toward(const Ray& ray, const Vec3& light_point,
                                                             Real t_max) {
    if (!(t_max > 0) || !std::isfinite(t_max)) return std::nullopt;
    const Real delta = glm::dot(light_point - ray.origin, ray.direction);
    const Real d = glm::length(light_point - ray.at(delta));
    // w = θ(t_max) − θ(0) = atan((t_max − Δ) / D) − atan(−Δ / D), as one atan2.
    const Real width = std::atan2(d * t_max, d * d - delta * (t_max - delta));
    if (!(d > 0) || !(width > 0) || !std::isfinite(d / width)) return std::nullopt;
    return EquiangularSampler(delta, d, width, t_max);
}

Real EquiangularSampler::sample(Real u) const {
    // θ = θ(0) + u w, t = Δ + D tan θ, rewritten with tan(a + b) = (tan a + tan b) / (1 − tan a tan b).
    const Real tau = std::tan(u * width_);
    const Real t = (d_ * d_ + delta_ * delta_) * tau / (d_ + delta_ * tau);
    // Rounding may step just outside the segment (or, past θ = π/2 from o, flip the denominator's sign).
    if (!(t >= 0)) return 0;
    return std::min(t, next_float_down(t_max_));
}

Real EquiangularSampler::pdf(Real t) const {
    if (!(t >= 0) || !(t < t_max_)) return 0;
    const Real x = t - delta_;
    return (d_ / width_) / (d_ * d_ + x * x);
}

}  // namespace rt
