// The one scattering interface of the course. A BSDF f(wo, wi) says how much of the light arriving from wi
// leaves toward wo: dL_o(wo) = f(wo, wi) L_i(wi) |cos θ_i| dω_i. It is a BRDF when all of it is reflected
// (wi on wo's side of the surface), and a BRDF plus a BTDF when light also passes through (chapter 07's
// glass). Directions point away from the surface; n is the unit normal on wo's side. Every material offers
//   eval(wo, wi, n):            f(wo, wi); 0 for a pair of directions it does not scatter between;
//   sample(wo, n, u, u_lobe):   a direction wi drawn with density pdf (solid angle), with f(wo, wi);
//   pdf(wo, wi, n):             the density of sample() at wi;
// and its flags, read by the path loops to decide what to do at a vertex without asking the material type.
// Energy conservation: ∫ f(wo, wi) |cos θ_i| dω_i <= 1 for every wo.
//
// Why virtual functions and not a std::variant: a variant's alternatives are fixed where it is declared, so
// chapter 07's dielectrics (and chapter 09's media) could only join by editing this chapter. A class derived
// from Bsdf lets a later chapter extend the model while chapter 04 stays unaware of it. A call through the
// interface is one indirect jump, what std::visit compiles to as well.
#pragma once

#include "rt/core/math.hpp"
#include "rt/core/ray_counts.hpp"

namespace rt {

struct BsdfFlags {
    bool delta = false;  // every value a Dirac delta (mirror, smooth glass): light samples never meet it
    bool transmission = false;  // light passes through too: sample() reads u_lobe to choose reflection or
                                // transmission, and may return a wi on the far side of n
    bool diffuse = false;       // scatters diffusely (Lambert): its bounces are counted as indirect rays
    bool black = false;         // scatters nothing: no shadow ray, no bounce
    // A delta lobe beside a lobe that is not (chapter 07's coated diffuse): not `delta`, so it takes light
    // samples, but only its own sample() draws the delta lobe, whose samples it marks BsdfSample::delta.
    bool delta_lobe = false;
};

struct BsdfSample {
    Vec3 wi{0, 0, 1};  // unit
    Color f{
        0};  // f(wo, wi); for a delta lobe, the factor that makes f |cos θ_i| / pdf the fraction scattered
    Real pdf = 0;  // solid-angle density; for a delta lobe, 1 by convention
    bool delta = false;  // drawn from a delta lobe: what the path meets next counts in full
    bool transmitted = false;  // wi is on the far side of the surface: the path crosses it
    // A factor of f that Russian roulette leaves out when it judges the path (chapter 06's loop hands chapter
    // 05's judged_scale the product of the samples' 1 / roulette_scale): 1 for every BSDF of this chapter; a
    // later chapter's BSDF sets it for a factor that the path gives back further on (chapter 07's glass).
    Real roulette_scale = 1;
};

// The kind of ray a sampled direction makes, for the run's counts: refraction through the surface, indirect
// off a diffuse one, reflection off anything else (mirror, glossy and retro-reflective lobes, glass).
inline RayKind ray_kind(const BsdfFlags& flags, bool transmitted) {
    return transmitted ? RayKind::kRefraction : flags.diffuse ? RayKind::kIndirect : RayKind::kReflection;
}

// |cos θ_i| on the side the BSDF scatters wi to: n · wi for a reflection, −n · wi through the surface.
inline Real scattering_cosine(const Vec3& wi, const Vec3& n, bool transmitted) {
    const Real c = glm::dot(wi, n);
    return transmitted ? -c : c;
}

class Bsdf {
  public:
    explicit Bsdf(BsdfFlags flags) : flags_(flags) {}
    virtual ~Bsdf() = default;

    const BsdfFlags& flags() const { return flags_; }
    virtual Color eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const = 0;
    // u in [0, 1)² warps to a direction; u_lobe in [0, 1) chooses the lobe of a BSDF with transmission (the
    // path loops draw it only for those, so a scene without glass draws the random numbers it always drew).
    virtual BsdfSample sample(const Vec3& wo, const Vec3& n, Vec2 u, Real u_lobe) const = 0;
    virtual Real pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const = 0;

  private:
    BsdfFlags flags_;
};

// The lesson's spelling of the three functions: eval(f, wo, wi, n), sample(f, wo, n, u), pdf(f, wo, wi, n).
inline Color eval(const Bsdf& f, const Vec3& wo, const Vec3& wi, const Vec3& n) {
    return f.eval(wo, wi, n);
}
inline BsdfSample sample(const Bsdf& f, const Vec3& wo, const Vec3& n, Vec2 u, Real u_lobe = 0) {
    return f.sample(wo, n, u, u_lobe);
}
inline Real pdf(const Bsdf& f, const Vec3& wo, const Vec3& wi, const Vec3& n) {
    return f.pdf(wo, wi, n);
}
inline bool is_delta(const Bsdf& f) {
    return f.flags().delta;
}
inline bool is_black(const Bsdf& f) {
    return f.flags().black;
}

}  // namespace rt
