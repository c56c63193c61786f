// Metals: a conductor reflects what the Fresnel equations of its complex index η + i k say (fresnel.hpp's
// fresnel_conductor, per colour channel) and absorbs the rest; nothing passes through. Smooth (roughness 0)
// it is a mirror whose colour changes with the angle; rough, the GGX microfacets of rough_dielectric.hpp,
// each facet a smooth conductor (Cook–Torrance; Walter et al. 2007's reflection term). In the frame n = +z:
//   smooth:     a delta lobe along the mirror direction, f |cos θ_i| / pdf = F(cos θ_o)
//   rough:      α = ggx_alpha(roughness), m = unit(wo + wi),
//               f = F(wo · m) D(m) G2(wo, wi) / (4 cos θ_o cos θ_i)
//               G2 = 1 / (1 + Λ(wo) + Λ(wi)), Λ(w) = 1 / G1(w) − 1 (Heitz 2014's height-correlated masking
//               and shadowing, pbrt-v4's and Mitsuba 3's choice for reflection: a facet high enough to be
//               seen from wo is likelier to see wi too, which the product G1(wo) G1(wi) ignores)
// Sampling: m by visible normals (sample_ggx_visible_normal, Heitz 2018), wi the mirror of wo about m:
//               pdf(wi) = D_wo(m) / (4 wo · m) = G1(wo) D(m) / (4 cos θ_o)
//               weight f cos θ_i / pdf = F(wo · m) G2 / G1(wo) ≤ F ≤ 1
// A wi below the surface is lost (pdf 0, f 0): with G2 < 1, the energy that single scattering loses (light
// a real rough surface would reflect again off a neighbouring facet; the lesson's furnace measures it).
#pragma once

#include "04_direct_lighting/bsdf.hpp"
#include "rt/core/math.hpp"

namespace rt {

class Conductor final : public Bsdf {
  public:
    // η, k >= 0 per channel (the scene loader's limits); roughness in [0, 1], 0 a smooth conductor.
    Conductor(const Color& eta, const Color& k, Real roughness);
    Color eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;
    BsdfSample sample(const Vec3& wo, const Vec3& n, Vec2 u, Real u_lobe) const override;
    Real pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const override;

    Color eta;
    Color k;
    Real alpha;  // 0 for a smooth conductor

  private:
    struct Scattering {
        Real f_over_fresnel = 0;  // D G2 / (4 cos θ_o cos θ_i)
        Real pdf = 0;
        Real cos_m = 0;  // wo · m, the angle Fresnel is taken at
    };
    // The rough lobe for local wo and wi (n = +z): the one computation behind eval, sample and pdf, so that
    // they agree to the last bit. Fresnel (complex arithmetic per channel) is left to those that need f.
    Scattering evaluate(const Vec3& wo, const Vec3& wi) const;
    Color f_of(const Scattering& e) const;
};

}  // namespace rt
