// A vertex of a path as the loop's steps see it: where it is, what it scatters toward a direction, the
// density with which it draws the direction that continues the path (the density MIS weighs light samples
// against), and that draw. This is chapter 06's surface vertex, which draws from the BSDF (or the strategy's
// hemisphere). The next-event estimate is a template over the vertex: a later chapter's vertex (one in a
// medium, a guided one) offers the same members, and the loop's extension (path_tracer.hpp) chooses the one
// at a surface.
#pragma once

#include <cmath>
#include <optional>

#include "02_intersection/hit.hpp"
#include "03_shadow_rays/ray_offset.hpp"
#include "03_shadow_rays/shadow_ray.hpp"
#include "04_direct_lighting/bsdf.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/light_sample.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "sample_stream.hpp"
#include "sampling_strategy.hpp"

namespace rt {

// What a vertex scatters toward a direction: the factor f and the cosine that weighs it (at a surface, the
// BSDF and |cos θ_i|). None when the cosine is not positive or f is black.
struct Scattering {
    Color f{0};
    Real cos = 0;
    bool none() const { return !(cos > 0) || is_black(f); }
};

// The direction that continues a path, and the cosine that weighs it.
struct Continuation {
    BsdfSample sample;
    Real cos_i = 0;
};

class BsdfVertex {
  public:
    // At `hit`, reached from −wo, scattering by `bsdf` (all three must outlive it). `bsdf_draws`: the BSDF's
    // own sampling draws the continuation whatever `strategy` says (as it must with next-event estimation
    // on).
    BsdfVertex(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, SamplingStrategy strategy, bool bsdf_draws,
               const RayOffset& offset)
        : hit_(hit), wo_(wo), bsdf_(bsdf), strategy_(strategy), bsdf_draws_(bsdf_draws), offset_(offset) {}

    // Where light samples are drawn from, and the normal an environment sample is drawn about.
    const Vec3& point() const { return hit_.point; }
    const Vec3& normal() const { return hit_.shading_normal; }
    // The shadow ray toward a light sample, and the ray toward a direction.
    ShadowRay shadow_ray(const LightSample& s) const { return spawn_shadow_ray(hit_, s.point, offset_); }
    Ray ray(const Vec3& wi) const { return spawn_ray(hit_, wi, offset_); }
    // f(wo, wi) and its cosine: a BSDF that transmits is lit from both sides, |cos θ_i| weighing light from
    // behind the surface.
    Scattering toward(const Vec3& wi) const {
        const Real dot_i = glm::dot(wi, hit_.shading_normal);
        const Real cos_i = bsdf_.flags().transmission ? std::abs(dot_i) : dot_i;
        if (!(cos_i > 0)) return {};
        return {bsdf_.eval(wo_, wi, hit_.shading_normal), cos_i};
    }
    // The density MIS weighs with: the BSDF's.
    Real pdf(const Vec3& wi) const { return bsdf_.pdf(wo_, wi, hit_.shading_normal); }
    // The continuation: the BSDF's own sampling at a delta BSDF (or one with a delta lobe), under the BSDF
    // strategy, and when `bsdf_draws`; the uniform or cosine hemisphere otherwise. None when it carries
    // nothing.
    std::optional<Continuation> sample(SampleStream rng) const {
        const BsdfFlags& flags = bsdf_.flags();
        const Vec3& n = hit_.shading_normal;
        Continuation c;
        BsdfSample& s = c.sample;
        const Vec2 u = rng.next_vec2();
        if (flags.delta || flags.delta_lobe || strategy_ == SamplingStrategy::kBrdf || bsdf_draws_) {
            // A BSDF with two lobes (reflection and transmission) takes one more number to choose between
            // them.
            s = bsdf_.sample(wo_, n, u, flags.transmission ? rng.next_real() : Real(0));
        } else {
            const bool uniform = strategy_ == SamplingStrategy::kUniform;
            const Vec3 local = uniform ? sample_uniform_hemisphere(u) : sample_cosine_hemisphere(u);
            s.wi = glm::normalize(make_frame(n).to_world(local));
            s.pdf = uniform ? uniform_hemisphere_pdf(local) : cosine_hemisphere_pdf(local.z);
            s.f = bsdf_.eval(wo_, s.wi, n);
        }
        c.cos_i = scattering_cosine(s.wi, n, s.transmitted);
        if (!(c.cos_i > 0) || !(s.pdf > 0) || is_black(s.f)) return std::nullopt;
        return c;
    }

  private:
    const Hit& hit_;
    Vec3 wo_;
    const Bsdf& bsdf_;
    SamplingStrategy strategy_;
    bool bsdf_draws_;
    const RayOffset& offset_;
};

}  // namespace rt
