// The course's one light sampler. It picks one light with probability proportional to its power, then a
// direction toward it with this chapter's samplers:
//   pdf(wi) = P(light) pdf_light(wi),   P(light) = Φ_light / Σ Φ.
// Power is what a light emits in all: Φ = π lum(Le) A for a one-sided Lambertian area light (a sphere's area
// is 4π r²), Φ = 4π lum(I) for a point light. The weights below drop the common factor π.
// For a planar light P = lum(L) A / W (W the sum of the weights) and pdf_light = d² / (cos θ_l A), so
//   pdf(wi) = lum(L) d² / (cos θ_l W):
// the area cancels, and MIS can weigh a BRDF sample that hit a quad or a triangle knowing only the emitter's
// radiance, its distance and its cosine. A hit names its light (Hit::light), so pdf() needs no search.
// Quads sampled by solid angle (quad_light_strategy.hpp) have pdf(wi) = P(light) / Ω where the spherical
// rectangle serves, and the planar formula above where area sampling stands in.
// It serves next-event estimation and MIS (chapter 06 on) and the start of light paths (chapter 08).
#pragma once

#include <optional>
#include <vector>

#include "02_intersection/hit.hpp"
#include "light_sample.hpp"
#include "light_set.hpp"
#include "quad_light_strategy.hpp"

namespace rt {

class LightPicker {
  public:
    // The area lights of `lights` (quads, then triangles, then spheres) and its point lights, in that order.
    // The environment is sampled apart: it has no position and no finite power.
    // Quads are sampled by `quad_lights`.
    explicit LightPicker(const LightSet& lights, QuadLightSampling quad_lights = QuadLightSampling::kArea);

    bool empty() const { return cdf_.empty(); }
    // The lights it picks among (0 when none emits any power).
    std::size_t light_count() const { return cdf_.size(); }
    // Σ Φ / π over every light.
    Real total_weight() const { return total_; }
    QuadLightSampling quad_lights() const { return quad_lights_; }
    std::size_t area_count() const { return quads_.size() + triangles_.size() + spheres_.size(); }
    // P(light): the probability of picking light `index` (quads, triangles, spheres, then points).
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

    const std::vector<QuadLight>& quads() const { return quads_; }
    const std::vector<TriangleLight>& triangles() const { return triangles_; }
    const std::vector<SphereLight>& spheres() const { return spheres_; }
    const std::vector<PointLight>& points() const { return points_; }

  private:
    std::vector<QuadLight> quads_;
    std::vector<TriangleLight> triangles_;
    std::vector<SphereLight> spheres_;
    std::vector<PointLight> points_;
    QuadLightSampling quad_lights_;
    std::vector<LightRef> by_hit_;
    std::vector<Real> weights_;  // Φ / π per light: lum(L) × area, 4 lum(I)
    std::vector<Real> cdf_;
    Real total_ = 0;
};

}  // namespace rt
