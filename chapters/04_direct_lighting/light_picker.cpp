#include "light_picker.hpp"

#include <algorithm>
#include <cmath>

#include "area_light_sampling.hpp"
#include "point_light_sampling.hpp"
#include "sphere_light_sampling.hpp"

namespace rt {

LightPicker::LightPicker(const LightSet& lights, QuadLightSampling quad_lights)
    : quads_(lights.quads),
      triangles_(lights.triangles),
      spheres_(lights.spheres),
      points_(lights.points),
      quad_lights_(quad_lights),
      by_hit_(lights.by_hit) {
    for (const QuadLight& q : quads_) weights_.push_back(luminance(q.radiance) * area_of(q));
    for (const TriangleLight& t : triangles_) weights_.push_back(luminance(t.radiance) * area_of(t));
    for (const SphereLight& s : spheres_) weights_.push_back(luminance(s.radiance) * area_of(s));
    for (const PointLight& p : points_) weights_.push_back(4 * luminance(p.intensity));
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

std::optional<LightSample> LightPicker::sample(const Vec3& p, Real u_pick, Vec2 u) const {
    if (empty()) return std::nullopt;
    const std::size_t i = pick(u_pick);
    const Real P = probability(i);
    // A light of zero power shares its cdf value with the one before it and is never picked.
    if (!(P > 0)) return std::nullopt;
    std::optional<LightSample> s;
    if (i < quads_.size()) {
        s = sample_quad_light(quads_[i], p, u, quad_lights_);
    } else if (i < quads_.size() + triangles_.size()) {
        s = sample_triangle_light(triangles_[i - quads_.size()], p, u);
    } else if (i < area_count()) {
        s = sample_sphere_light(spheres_[i - quads_.size() - triangles_.size()], p, u);
    } else {
        s = sample_point_light(points_[i - area_count()], p);
    }
    if (s) s->pdf *= P;
    return s;
}

Real LightPicker::pdf(const Vec3& p, const Vec3& wi, const Hit& hit) const {
    if (empty() || hit.light < 0 || std::size_t(hit.light) >= by_hit_.size()) return 0;
    const LightRef ref = by_hit_[std::size_t(hit.light)];
    switch (ref.list) {
        case LightRef::List::kSpheres: {
            const std::size_t first_sphere = quads_.size() + triangles_.size();
            return probability(first_sphere + ref.index) * sphere_light_pdf(spheres_[ref.index], p);
        }
        case LightRef::List::kQuads:
        case LightRef::List::kTriangles: {
            // A planar light: lum(L) d² / (cos θ_l W).
            const Color& L = ref.list == LightRef::List::kQuads ? quads_[ref.index].radiance
                                                                : triangles_[ref.index].radiance;
            const Real cos_light = -glm::dot(hit.normal, wi);
            if (!(cos_light > 0)) return 0;
            if (ref.list == LightRef::List::kQuads && quad_lights_ == QuadLightSampling::kSolidAngle) {
                // P(light) / Ω where the spherical rectangle drew wi.
                if (const auto view = solid_angle_view(quads_[ref.index], p))
                    return probability(ref.index) * Real(1 / view->solid_angle());
            }
            return luminance(L) * hit.t * hit.t / (cos_light * total_);
        }
        case LightRef::List::kNone:
            break;
    }
    return 0;
}

}  // namespace rt
