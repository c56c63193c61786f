#include "refraction_materials.hpp"

#include "coated_diffuse.hpp"
#include "conductor.hpp"
#include "dielectric.hpp"
#include "rough_dielectric.hpp"

namespace rt {

MaterialHooks refraction_materials(Transport transport) {
    MaterialHooks hooks = direct_lighting_materials();
    MaterialModel& dielectric = hooks.models["dielectric"];
    dielectric.bsdf = [transport](const Material& m, bool outside, BsdfAtHit& at) -> const Bsdf& {
        const Real eta = outside ? m.ior : 1 / m.ior;
        // Index-matched (η = 1) glass is invisible however rough: every facet passes light straight on.
        if (m.roughness > 0 && m.ior != 1) return at.emplace<RoughDielectric>(m.roughness, eta, transport);
        return at.emplace<SmoothDielectric>(eta, transport);
    };
    dielectric.two_sided = true;
    dielectric.interior = [](const Material& m) -> std::unique_ptr<Medium> {
        // A scattering medium without chapter 09: what it takes out of a ray (σ_a + σ_s), as absorption.
        const Color absorption = m.medium ? m.medium->sigma_t() : m.absorption;
        if (is_black(absorption)) return nullptr;
        return std::make_unique<AbsorbingMedium>(absorption);
    };
    hooks.models["conductor"].bsdf = [](const Material& m, bool, BsdfAtHit& at) -> const Bsdf& {
        return at.emplace<Conductor>(m.eta, m.k, m.roughness);
    };
    hooks.models["coateddiffuse"].bsdf = [](const Material& m, bool, BsdfAtHit& at) -> const Bsdf& {
        return at.emplace<CoatedDiffuse>(m.albedo, m.ior);
    };
    return hooks;
}

}  // namespace rt
