#include "guided_vertex.hpp"

namespace rt {

std::optional<Continuation> GuidedVertex::sample(SampleStream rng) const {
    if (!guide_) return BsdfVertex::sample(rng);
    // EXERCISE(ch12.one_sample_mis) § One-sample MIS
    if (rng.next_real() < alpha_) {
        const Vec3 wi = guide_->sample(rng.next_vec2()).w;
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
