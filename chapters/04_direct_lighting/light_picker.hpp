// The course's one light sampler. It picks one light with probability proportional to its power, then a
// direction toward it with the light's own sampler (light.hpp):
//   pdf(wi) = P(light) pdf_light(wi),   P(light) = Φ_light / Σ Φ.
// Power is what a light emits in all: Φ = π lum(Le) A for a one-sided Lambertian area light (a sphere's area
// is 4π r²), Φ = 4π lum(I) for a point light. The weights (Light::power_weight) drop the common factor π.
// A hit names its light (Hit::light), so pdf() needs no search: it asks that light, which knows how it was
// sampled (a planar light's density needs only its radiance, distance and cosine: area_light_sampling.hpp).
// It serves next-event estimation and MIS (chapter 06 on) and the start of light paths (chapter 08).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "02_intersection/hit.hpp"
#include "light_sample.hpp"
#include "light_set.hpp"
#include "quad_light_strategy.hpp"

namespace rt {

class LightPicker {
  public:
    // The lights of `lights`, in its order. The environment is sampled apart: it has no position and no
    // finite power.
    // Quads are sampled by `quad_lights`.
    explicit LightPicker(const LightSet& lights, QuadLightSampling quad_lights = QuadLightSampling::kArea);

    bool empty() const { return cdf_.empty(); }
    // The lights it picks among (0 when none emits any power).
    std::size_t light_count() const { return cdf_.size(); }
    // Σ Φ / π over every light.
    Real total_weight() const { return total_; }
    QuadLightSampling quad_lights() const { return quad_lights_; }
    // P(light): the probability of picking light `index` (LightSet::lights' order).
    Real probability(std::size_t index) const;
    // The running sums of P(light), the last 1 (empty when none emits any power): what pick() searches.
    const std::vector<Real>& cdf() const { return cdf_; }
    // The light u_pick in [0, 1) chooses: the first with cdf > u_pick (cdf = running sum of P).
    std::size_t pick(Real u_pick) const;

    // One sample from p: a light chosen by u_pick, a direction toward it from u; the pdf includes P(light)
    // (a point light: pdf = P, a delta). Nothing when p cannot see that light's emitting side.
    std::optional<LightSample> sample(const Vec3& p, Real u_pick, Vec2 u) const;
    // The density with which sample() draws wi from p, when the ray p + t wi first meets the light of `hit`
    // on its emitting side. 0 when `hit` is on no sampled light (Hit::light < 0, or a degenerate one).
    Real pdf(const Vec3& p, const Vec3& wi, const Hit& hit) const;

    // Light `index`, in LightSet::lights' order.
    const Light& light(std::size_t index) const { return *lights_[index]; }
    // Where Hit::light k is among the lights (LightSet::by_hit), −1 when on none.
    int index_of_hit(int light) const;

  private:
    std::vector<std::shared_ptr<const Light>> lights_;
    QuadLightSampling quad_lights_;
    std::vector<int> by_hit_;
    std::vector<Real> weights_;  // Φ / π per light (Light::power_weight)
    std::vector<Real> cdf_;
    Real total_ = 0;
};

}  // namespace rt
