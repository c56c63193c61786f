#include "refraction_materials.hpp"

#include "dielectric.hpp"

namespace rt {

MaterialHooks refraction_materials() {
    MaterialHooks hooks;
    hooks.dielectric = [](const Material& m, bool outside, Transport transport) -> std::unique_ptr<Bsdf> {
        const Real eta = outside ? m.ior : 1 / m.ior;
        return std::make_unique<SmoothDielectric>(eta, transport);
    };
    hooks.dielectric_interior = [](const Material& m) -> std::unique_ptr<Medium> {
        if (is_black(m.absorption)) return nullptr;
        return std::make_unique<AbsorbingMedium>(m.absorption);
    };
    return hooks;
}

}  // namespace rt
