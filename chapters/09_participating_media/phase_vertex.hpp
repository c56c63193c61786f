// A vertex in a medium, as chapter 06's next-event estimate sees a vertex (06_monte_carlo/bsdf_vertex.hpp):
// the phase function in the place of the BSDF, no surface (so no cosine, no ray offset, no normal: a constant
// environment is drawn over the whole sphere), and the phase function's sampling for the continuation.
#pragma once

#include "03_shadow_rays/shadow_ray.hpp"
#include "04_direct_lighting/light_sample.hpp"
#include "06_monte_carlo/bsdf_vertex.hpp"
#include "06_monte_carlo/sample_stream.hpp"
#include "phase_function.hpp"

namespace rt {

class PhaseVertex {
  public:
    // At p, reached from −wo, scattering by `phase` (which must outlive it).
    PhaseVertex(const Vec3& p, const Vec3& wo, const PhaseFunction& phase) : p_(p), wo_(wo), phase_(phase) {}

    const Vec3& point() const { return p_; }
    Vec3 normal() const { return Vec3(0); }
    // The shadow ray stops short of the light's point, as chapter 03's does.
    ShadowRay shadow_ray(const LightSample& s) const {
        return {{p_, s.wi}, (1 - kShadowEpsilon) * s.distance};
    }
    Ray ray(const Vec3& wi) const { return {p_, wi}; }
    // No BSDF and no cosine: f is 1, and p(wo, wi) weighs it where a surface's cosine would.
    Scattering toward(const Vec3& wi) const { return {Color(1), phase_.eval(wo_, wi)}; }
    Real pdf(const Vec3& wi) const { return phase_.pdf(wo_, wi); }
    PhaseSample sample(SampleStream rng) const { return phase_.sample(wo_, rng.next_vec2()); }

  private:
    Vec3 p_, wo_;
    const PhaseFunction& phase_;
};

}  // namespace rt
