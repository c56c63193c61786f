#include "guided_vertex.hpp"

namespace rt {

namespace {

// w mirrored in the plane of the surface with normal n.
Vec3 mirrored(const Vec3& w, const Vec3& n) {
    return w - Real(2) * glm::dot(w, n) * n;
}

}  // namespace

Real GuidedVertex::guide_pdf(const Vec3& wi) const {
    if (transmits_) return guide_->pdf(wi);
    if (!(glm::dot(wi, normal()) > 0)) return 0;
    return guide_->pdf(wi) + guide_->pdf(mirrored(wi, normal()));
}

Vec3 GuidedVertex::guide_sample(Vec2 u) const {
    const Vec3 w = guide_->sample(u).w;
    if (transmits_ || glm::dot(w, normal()) > 0) return w;
    return glm::normalize(mirrored(w, normal()));
}

std::optional<Continuation> GuidedVertex::sample(SampleStream rng) const {
    if (!guide_) return BsdfVertex::sample(rng);
    // EXERCISE(ch12.one_sample_mis) § 5. One-sample MIS
    if (rng.next_real() < alpha_) {
        const Vec3 wi = guide_sample(rng.next_vec2());
        const Scattering f = toward(wi);
        if (f.none()) return std::nullopt;
        Continuation c;
        c.sample.wi = wi;
        c.sample.f = f.f;
        c.sample.pdf = pdf(wi);
        c.sample.transmitted = glm::dot(wi, normal()) < 0;
        c.cos_i = f.cos;
        if (!(c.sample.pdf > 0)) return std::nullopt;
        return c;
    }
    std::optional<Continuation> c = BsdfVertex::sample(rng);
    if (c) c->sample.pdf = pdf(c->sample.wi);
    return c;
    // END EXERCISE
}

}  // namespace rt
