// A surface vertex that samples its continuation from a mixture: with probability α from the guide (the
// incident light learned at this place, guiding_field.hpp), otherwise from the BSDF, as chapter 06's vertex
// does. One-sample MIS (Veach's "one-sample model", the balance heuristic over the two): whichever drew wi,
// the path weighs it by the mixture's density
//   p(wi) = α p_guide(wi) + (1 − α) p_bsdf(wi),     β ← β f(wo, wi) |cos θ_i| / p(wi),
// which is positive wherever the BSDF's is, so the estimate stays unbiased however badly the guide learned;
// next-event estimation weighs its light samples against the same p (the loop asks pdf()). A delta BSDF,
// which no other direction can serve, is never guided: its vertex is chapter 06's.
// At a surface that only reflects, the guide is folded onto the hemisphere it lights: a direction drawn
// below the surface is mirrored in it, w' = w − 2 (w · n) n, so p_guide(w) = g(w) + g(w − 2 (w · n) n) above
// and 0 below. A guide learned over a leaf that holds surfaces facing several ways wastes no sample on the
// inside of this one.
#pragma once

#include <optional>

#include "06_monte_carlo/bsdf_vertex.hpp"
#include "directional_quadtree.hpp"

namespace rt {

class GuidedVertex : public BsdfVertex {
  public:
    // Chapter 06's vertex at a BSDF that `transmits` light or not, guided by `guide` with probability
    // `alpha` (no guide: it is chapter 06's, drawing the same numbers).
    GuidedVertex(const BsdfVertex& vertex, bool transmits, const DirectionalQuadtree* guide, Real alpha)
        : BsdfVertex(vertex), transmits_(transmits), guide_(guide), alpha_(alpha) {}

    // The guide's density, folded onto the lit hemisphere unless the BSDF transmits.
    Real guide_pdf(const Vec3& wi) const;
    // The mixture's density.
    Real pdf(const Vec3& wi) const {
        const Real bsdf = BsdfVertex::pdf(wi);
        return guide_ ? alpha_ * guide_pdf(wi) + (1 - alpha_) * bsdf : bsdf;
    }
    // One number chooses the strategy; the chosen one draws wi; the mixture's density weighs it.
    std::optional<Continuation> sample(SampleStream rng) const;

  private:
    // A direction drawn from the guide (folded as guide_pdf says).
    Vec3 guide_sample(Vec2 u) const;

    bool transmits_;
    const DirectionalQuadtree* guide_;
    Real alpha_;
};

}  // namespace rt
