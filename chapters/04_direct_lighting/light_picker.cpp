#include "light_picker.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

LightPicker::LightPicker(const LightSet& lights, QuadLightSampling quad_lights)
    : lights_(lights.lights), quad_lights_(quad_lights), by_hit_(lights.by_hit) {
    for (const auto& light : lights_) weights_.push_back(light->power_weight());
    for (Real& w : weights_) w = std::isfinite(w) ? std::max(w, Real(0)) : Real(0);
    double sum = 0;
    for (Real w : weights_) sum += double(w);
    total_ = Real(sum);
    if (!(sum > 0)) {
        weights_.clear();
        return;
    }
    double running = 0;
    for (Real w : weights_) {
        running += double(w);
        cdf_.push_back(Real(running / sum));
    }
    cdf_.back() = 1;
}

Real LightPicker::probability(std::size_t index) const {
    return index < weights_.size() ? weights_[index] / total_ : Real(0);
}

std::size_t LightPicker::pick(Real u_pick) const {
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u_pick);
    return std::min(std::size_t(it - cdf_.begin()), cdf_.size() - 1);
}

int LightPicker::index_of_hit(int light) const {
    return light >= 0 && std::size_t(light) < by_hit_.size() ? by_hit_[std::size_t(light)] : -1;
}

std::optional<LightSample> LightPicker::sample(const Vec3& p, Real u_pick, Vec2 u) const {
    if (empty()) return std::nullopt;
    const std::size_t i = pick(u_pick);
    const Real P = probability(i);
    // A light of zero power shares its cdf value with the one before it and is never picked.
    if (!(P > 0)) return std::nullopt;
    std::optional<LightSample> s = lights_[i]->sample(p, u, quad_lights_);
    if (s) s->pdf *= P;
    return s;
}

Real LightPicker::pdf(const Vec3& p, const Vec3& wi, const Hit& hit) const {
    const int index = index_of_hit(hit.light);
    if (empty() || index < 0) return 0;
    const std::size_t i = std::size_t(index);
    return lights_[i]->pdf(p, wi, hit, PickedLight{probability(i), total_, quad_lights_});
}

}  // namespace rt
