// A surface vertex that samples its continuation from a mixture: with probability α from the guide (the
// incident light learned at this place, guiding_field.hpp), otherwise from the BSDF, as chapter 06's vertex
// does. One-sample MIS (Veach's "one-sample model", the balance heuristic over the two): whichever drew wi,
// the path weighs it by the mixture's density
//   p(wi) = α p_guide(wi) + (1 − α) p_bsdf(wi),     β ← β f(wo, wi) |cos θ_i| / p(wi),
// which is positive wherever the BSDF's is, so the estimate stays unbiased however badly the guide learned;
// next-event estimation weighs its light samples against the same p (the loop asks pdf()). A delta BSDF,
// which no other direction can serve, is never guided: its vertex is chapter 06's.
#pragma once

#include <optional>

#include "06_monte_carlo/bsdf_vertex.hpp"
#include "directional_quadtree.hpp"

namespace rt {

class GuidedVertex : public BsdfVertex {
  public:
    // Chapter 06's vertex, guided by `guide` with probability `alpha` (no guide: it is chapter 06's, drawing
    // the same numbers).
    GuidedVertex(const BsdfVertex& vertex, const DirectionalQuadtree* guide, Real alpha)
        : BsdfVertex(vertex), guide_(guide), alpha_(alpha) {}

    // The mixture's density.
    Real pdf(const Vec3& wi) const {
        const Real bsdf = BsdfVertex::pdf(wi);
        return guide_ ? alpha_ * guide_->pdf(wi) + (1 - alpha_) * bsdf : bsdf;
    }
    // One number chooses the strategy; the chosen one draws wi; the mixture's density weighs it.
    std::optional<Continuation> sample(SampleStream rng) const;

  private:
    const DirectionalQuadtree* guide_;
    Real alpha_;
};

}  // namespace rt
