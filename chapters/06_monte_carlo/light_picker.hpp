// Next-event estimation picks one area light per path vertex, with probability proportional to its power
// (∝ lum(L) × area; a sphere's area is 4π r²), then a direction toward it with chapter 04's samplers:
//   pdf(wi) = P(light) pdf_light(wi).
// For a planar light P = lum(L) A / W (W the sum over all lights) and pdf_light = d² / (cos θ_l A), so
//   pdf(wi) = lum(L) d² / (cos θ_l W):
// the area cancels, and MIS can weigh a BRDF sample that hit a quad or a triangle knowing only the emitter's
// radiance, its distance and its cosine.
#pragma once

#include <optional>
#include <vector>

#include "hit.hpp"
#include "light_sample.hpp"
#include "light_set.hpp"

namespace rt {

class LightPicker {
  public:
    explicit LightPicker(const LightSet& lights);

    bool empty() const { return cdf_.empty(); }
    // P(light): the probability of picking area light `index` (quads, then triangles, then spheres).
    Real probability(std::size_t index) const;
    // The light u_pick in [0, 1) chooses: the first with cdf > u_pick (cdf = running sum of P).
    std::size_t pick(Real u_pick) const;

    // One sample from p: a light chosen by u_pick, a direction toward it from u; the pdf includes P(light).
    // Nothing when p cannot see that light's emitting side.
    std::optional<LightSample> sample(const Vec3& p, Real u_pick, Vec2 u) const;
    // The density with which sample() draws wi from p, when the ray p + t wi first meets an emitter of
    // radiance `emission` at `hit` (front side). 0 when that emitter is not one of the sampled lights.
    Real pdf(const Vec3& p, const Vec3& wi, const Hit& hit, const Color& emission) const;

  private:
    std::vector<QuadLight> quads_;
    std::vector<TriangleLight> triangles_;
    std::vector<SphereLight> spheres_;
    std::vector<Real> weights_;  // lum(L) × area, per light
    std::vector<Real> cdf_;
    Real total_ = 0;
};

}  // namespace rt
