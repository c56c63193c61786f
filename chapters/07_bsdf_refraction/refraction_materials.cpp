#include "refraction_materials.hpp"

#include "conductor.hpp"
#include "dielectric.hpp"
#include "rough_dielectric.hpp"

namespace rt {

MaterialHooks refraction_materials(Transport transport) {
    MaterialHooks hooks;
    hooks.dielectric = [transport](const Material& m, bool outside) -> std::unique_ptr<Bsdf> {
        const Real eta = outside ? m.ior : 1 / m.ior;
        // Index-matched (η = 1) glass is invisible however rough: every facet passes light straight on.
        if (m.roughness > 0 && m.ior != 1)
            return std::make_unique<RoughDielectric>(m.roughness, eta, transport);
        return std::make_unique<SmoothDielectric>(eta, transport);
    };
    hooks.dielectric_interior = [](const Material& m) -> std::unique_ptr<Medium> {
        // A scattering medium without chapter 09: what it takes out of a ray (σ_a + σ_s), as absorption.
        const Color absorption = m.medium ? m.medium->sigma_t() : m.absorption;
        if (is_black(absorption)) return nullptr;
        return std::make_unique<AbsorbingMedium>(absorption);
    };
    hooks.conductor = [](const Material& m) -> std::unique_ptr<Bsdf> {
        return std::make_unique<Conductor>(m.eta, m.k, m.roughness);
    };
    return hooks;
}

}  // namespace rt
