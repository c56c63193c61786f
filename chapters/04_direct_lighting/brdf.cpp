#include "brdf.hpp"

#include <algorithm>
#include <cmath>

#include "frame.hpp"
#include "sampling.hpp"

namespace rt {
namespace {

bool above(const Vec3& wo, const Vec3& wi, const Vec3& n) {
    return glm::dot(wo, n) > 0 && glm::dot(wi, n) > 0;
}

// cos^e α for cos α = max(0, wi · axis); 0⁰ is taken as 1 only inside the lobe (cos α > 0).
Real lobe_power(const Vec3& wi, const Vec3& axis, Real exponent) {
    const Real c = std::min(Real(1), glm::dot(wi, axis));
    return c > 0 ? std::pow(c, exponent) : Real(0);
}

// Lambert: f = ρ / π when wo and wi are both above the surface, else 0.
Color lambert_eval(const LambertBrdf& lambert, const Vec3& wo, const Vec3& wi, const Vec3& n) {
    // EXERCISE(ch04.lambert)
    return above(wo, wi, n) ? lambert.albedo * kInvPi : Color(0);
    // END EXERCISE
}

// The mirror's one direction wi = r(wo), with f = R / cos θ_i and pdf 1 (a delta), so that f cos θ_i / pdf =
// R; nothing (f = 0) when r(wo) is not above the surface.
BrdfSample mirror_sample(const MirrorBrdf& mirror, const Vec3& wo, const Vec3& n) {
    // EXERCISE(ch04.mirror)
    BrdfSample s;
    s.wi = reflect(wo, n);
    const Real cos_i = glm::dot(s.wi, n);
    s.f = cos_i > 0 ? mirror.reflectance / cos_i : Color(0);
    s.pdf = 1;
    s.delta = true;
    return s;
    // END EXERCISE
}

// The glossy BRDF's normalized lobe f = ρ (e + 2) / (2π) cos^e α around `axis` (r(wo) for glossy), 0 unless
// wo and wi are both above the surface.
Color lobe_eval(const Color& albedo, Real exponent, const Vec3& axis, const Vec3& wo, const Vec3& wi,
                const Vec3& n) {
    // EXERCISE(ch04.glossy)
    if (!above(wo, wi, n)) return Color(0);
    return albedo * ((exponent + 2) * Real(0.5) * kInvPi * lobe_power(wi, axis, exponent));
    // END EXERCISE
}

// Retro-reflective: the same normalized lobe, around wo itself.
Color retroreflective_eval(const RetroreflectiveBrdf& retro, const Vec3& wo, const Vec3& wi, const Vec3& n) {
    // EXERCISE(ch04.retroreflective)
    return lobe_eval(retro.albedo, retro.exponent, wo, wo, wi, n);
    // END EXERCISE
}

// pdf = (e + 1) / (2π) cos^e α: the density of sample_power_cosine about `axis`.
Real lobe_pdf(Real exponent, const Vec3& axis, const Vec3& wi) {
    return (exponent + 1) * Real(0.5) * kInvPi * lobe_power(wi, axis, exponent);
}

BrdfSample lobe_sample(const Color& albedo, Real exponent, const Vec3& axis, const Vec3& wo, const Vec3& n,
                       Vec2 u) {
    BrdfSample s;
    s.wi = glm::normalize(make_frame(axis).to_world(sample_power_cosine(u, exponent)));
    s.f = lobe_eval(albedo, exponent, axis, wo, s.wi, n);  // 0 when the lobe dips below the surface
    s.pdf = lobe_pdf(exponent, axis, s.wi);
    return s;
}

struct Eval {
    const Vec3& wo;
    const Vec3& wi;
    const Vec3& n;
    Color operator()(const LambertBrdf& b) const { return lambert_eval(b, wo, wi, n); }
    Color operator()(const MirrorBrdf&) const { return Color(0); }
    Color operator()(const GlossyBrdf& b) const {
        return lobe_eval(b.albedo, b.exponent, reflect(wo, n), wo, wi, n);
    }
    Color operator()(const RetroreflectiveBrdf& b) const { return retroreflective_eval(b, wo, wi, n); }
};

struct Sample {
    const Vec3& wo;
    const Vec3& n;
    Vec2 u;
    BrdfSample operator()(const LambertBrdf& b) const {
        BrdfSample s;
        s.wi = glm::normalize(make_frame(n).to_world(sample_cosine_hemisphere(u)));
        s.f = lambert_eval(b, wo, s.wi, n);
        s.pdf = std::max(Real(0), glm::dot(s.wi, n)) * kInvPi;
        return s;
    }
    BrdfSample operator()(const MirrorBrdf& b) const { return mirror_sample(b, wo, n); }
    BrdfSample operator()(const GlossyBrdf& b) const {
        return lobe_sample(b.albedo, b.exponent, reflect(wo, n), wo, n, u);
    }
    BrdfSample operator()(const RetroreflectiveBrdf& b) const {
        return lobe_sample(b.albedo, b.exponent, wo, wo, n, u);
    }
};

struct Pdf {
    const Vec3& wo;
    const Vec3& wi;
    const Vec3& n;
    Real operator()(const LambertBrdf&) const { return std::max(Real(0), glm::dot(wi, n)) * kInvPi; }
    Real operator()(const MirrorBrdf&) const { return 0; }
    Real operator()(const GlossyBrdf& b) const { return lobe_pdf(b.exponent, reflect(wo, n), wi); }
    Real operator()(const RetroreflectiveBrdf& b) const { return lobe_pdf(b.exponent, wo, wi); }
};

}  // namespace

Real phong_exponent(Real roughness) {
    const Real r = std::max(roughness, Real(1e-3));
    return std::max(Real(0), 2 / (r * r) - 2);
}

Brdf brdf_of(const Material& m, const Brdf& dielectric_stand_in) {
    switch (m.type) {
        case MaterialType::kDiffuse:
            return LambertBrdf{m.albedo};
        case MaterialType::kMirror:
            return MirrorBrdf{m.reflectance};
        case MaterialType::kGlossy:
            return GlossyBrdf{m.albedo, phong_exponent(m.roughness)};
        case MaterialType::kRetroreflective:
            return RetroreflectiveBrdf{m.albedo, phong_exponent(m.roughness)};
        case MaterialType::kDielectric:
            return dielectric_stand_in;
    }
    return LambertBrdf{m.albedo};
}

Color eval(const Brdf& brdf, const Vec3& wo, const Vec3& wi, const Vec3& n) {
    return std::visit(Eval{wo, wi, n}, brdf);
}

BrdfSample sample(const Brdf& brdf, const Vec3& wo, const Vec3& n, Vec2 u) {
    return std::visit(Sample{wo, n, u}, brdf);
}

Real pdf(const Brdf& brdf, const Vec3& wo, const Vec3& wi, const Vec3& n) {
    return std::visit(Pdf{wo, wi, n}, brdf);
}

bool is_delta(const Brdf& brdf) {
    return std::holds_alternative<MirrorBrdf>(brdf);
}

bool is_black(const Brdf& brdf) {
    return std::visit(
        [](const auto& b) {
            if constexpr (std::is_same_v<std::decay_t<decltype(b)>, MirrorBrdf>) {
                return is_black(b.reflectance);
            } else {
                return is_black(b.albedo);
            }
        },
        brdf);
}

Brdf without_lobes(const Brdf& brdf) {
    if (const auto* g = std::get_if<GlossyBrdf>(&brdf)) return LambertBrdf{g->albedo};
    if (const auto* r = std::get_if<RetroreflectiveBrdf>(&brdf)) return LambertBrdf{r->albedo};
    return brdf;
}

}  // namespace rt
