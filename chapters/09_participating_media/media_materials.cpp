#include "media_materials.hpp"

#include "07_bsdf_refraction/dielectric.hpp"
#include "07_bsdf_refraction/refraction_materials.hpp"
#include "homogeneous_medium.hpp"

namespace rt {

MaterialHooks media_materials() {
    MaterialHooks hooks = refraction_materials();
    hooks.medium = [](const MediumDesc& medium) -> std::unique_ptr<Medium> {
        if (medium.scatters()) return std::make_unique<HomogeneousMedium>(medium);
        if (is_black(medium.sigma_a)) return nullptr;
        return std::make_unique<AbsorbingMedium>(medium.sigma_a);
    };
    return hooks;
}

bool index_matched(const Bsdf& bsdf) {
    const auto* glass = dynamic_cast<const SmoothDielectric*>(&bsdf);
    return glass && glass->eta == 1;
}

}  // namespace rt
