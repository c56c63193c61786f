#include "light_picker.hpp"

#include <algorithm>

#include "area_light_sampling.hpp"
#include "sphere_light_sampling.hpp"

namespace rt {

LightPicker::LightPicker(const LightSet& lights)
    : quads_(lights.quads), triangles_(lights.triangles), spheres_(lights.spheres) {
    for (const QuadLight& q : quads_) weights_.push_back(luminance(q.radiance) * q.area);
    for (const TriangleLight& t : triangles_) weights_.push_back(luminance(t.radiance) * t.area);
    for (const SphereLight& s : spheres_)
        weights_.push_back(luminance(s.radiance) * 4 * kPi * s.radius * s.radius);
    double sum = 0;
    for (Real w : weights_) sum += double(std::max(Real(0), w));
    total_ = Real(sum);
    if (!(sum > 0)) {
        weights_.clear();
        return;
    }
    double running = 0;
    for (Real w : weights_) {
        running += double(std::max(Real(0), w));
        cdf_.push_back(Real(running / sum));
    }
    cdf_.back() = 1;
}

Real LightPicker::probability(std::size_t index) const {
    return std::max(Real(0), weights_[index]) / total_;
}

std::size_t LightPicker::pick(Real u_pick) const {
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u_pick);
    return std::min(std::size_t(it - cdf_.begin()), cdf_.size() - 1);
}

std::optional<LightSample> LightPicker::sample(const Vec3& p, Real u_pick, Vec2 u) const {
    if (empty()) return std::nullopt;
    const std::size_t i = pick(u_pick);
    std::optional<LightSample> s;
    if (i < quads_.size()) {
        s = sample_quad_light(quads_[i], p, u);
    } else if (i < quads_.size() + triangles_.size()) {
        s = sample_triangle_light(triangles_[i - quads_.size()], p, u);
    } else {
        s = sample_sphere_light(spheres_[i - quads_.size() - triangles_.size()], p, u);
    }
    if (s) s->pdf *= probability(i);
    return s;
}

Real LightPicker::pdf(const Vec3& p, const Vec3& wi, const Hit& hit, const Color& emission) const {
    if (empty()) return 0;
    // A sphere light: the hit lies on it, its normal pointing away from the centre.
    const std::size_t first_sphere = quads_.size() + triangles_.size();
    for (std::size_t k = 0; k < spheres_.size(); ++k) {
        const SphereLight& s = spheres_[k];
        const Vec3 out = hit.point - s.center;
        const Real d = glm::length(out);
        if (std::abs(d - s.radius) <= Real(1e-3) * s.radius && glm::dot(out, hit.normal) > 0) {
            return probability(first_sphere + k) * sphere_light_pdf(s, p);
        }
    }
    // A planar light: lum(L) d² / (cos θ_l W).
    const Real cos_light = -glm::dot(hit.normal, wi);
    if (!(cos_light > 0)) return 0;
    return luminance(emission) * hit.t * hit.t / (cos_light * total_);
}

}  // namespace rt
