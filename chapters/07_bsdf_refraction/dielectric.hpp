// The smooth dielectric BSDF = BRDF + BTDF: a delta lobe along the mirror direction r(wo) that reflects the
// fraction R and a delta lobe along the refracted direction wt that transmits T = 1 − R (R the exact Fresnel
// reflectance). It is sampled by choosing reflection with probability R and transmission with probability T,
// each choice weighted by its f cos θ / pdf (the lesson derives them): the Fresnel factor becomes the choice.
// Radiance across the interface: L / η² is what is conserved along a ray through a lossless interface, so a
// camera path crossing into glass scales what it brings back (and the inverse crossing out: they cancel on a
// path that goes in and out). Light paths (chapter 08) carry importance, which does not scale: the BTDF is
// not symmetric.
#pragma once

#include "04_direct_lighting/bsdf.hpp"
#include "04_direct_lighting/medium.hpp"
#include "rt/core/math.hpp"

namespace rt {

// What a path carries: radiance (from the camera, chapters 04–07) or importance (from the lights, chapter
// 08, which builds its material table with refraction_materials(Transport::kImportance)). A BSDF that
// refracts treats them differently: radiance crossing an interface scales, importance does not (the BTDF is
// not symmetric).
enum class Transport { kRadiance, kImportance };

enum class DielectricLobe { kReflection, kTransmission };

struct DielectricSample {
    Vec3 wi{0, 0, 1};  // unit
    Color weight{1};   // f cos θ_i / pdf of the lobe chosen, pdf its probability (the lesson derives it)
    DielectricLobe lobe = DielectricLobe::kReflection;
    Real probability = 1;  // of the lobe chosen: R or T
};

// One sample of the BSDF for wo (unit, n · wo >= 0, n the normal on wo's side, η = η_t / η_i); u in [0, 1)
// chooses the lobe: reflection when u < R. Under total internal reflection R = 1: always reflection.
DielectricSample sample_dielectric(const Vec3& wo, const Vec3& n, Real eta, Real u);

// The smooth dielectric as a Bsdf of the course's material model (chapter 04's bsdf.hpp): delta and
// transmitting, its lobe chosen by u_lobe through sample_dielectric. η is fixed per object: the material
// table holds one for each side, η = ior seen from outside and 1 / ior from inside. A sampled lobe's
// f |cos θ_i| / pdf is the weight above for radiance, and 1 either way for importance (chapter 08).
class SmoothDielectric final : public Bsdf {
  public:
    SmoothDielectric(Real eta, Transport transport);
    Color eval(const Vec3&, const Vec3&, const Vec3&) const override { return Color(0); }
    BsdfSample sample(const Vec3& wo, const Vec3& n, Vec2 u, Real u_lobe) const override;
    Real pdf(const Vec3&, const Vec3&, const Vec3&) const override { return 0; }

    Real eta;
    Transport transport;
};

// Beer–Lambert: the fraction of radiance left after a distance d inside a medium of absorption coefficient
// σ_a (per unit length): T = exp(−σ_a d), per colour channel. σ_a = 0 gives exactly 1 for every d, even ∞.
Color beer_lambert(const Color& absorption, Real distance);

// What fills absorbing glass: Beer–Lambert with σ_a = the material's "absorption".
class AbsorbingMedium final : public Medium {
  public:
    explicit AbsorbingMedium(const Color& absorption_) : absorption(absorption_) {}
    Color transmittance(Real distance) const override { return beer_lambert(absorption, distance); }

    Color absorption;
};

}  // namespace rt
