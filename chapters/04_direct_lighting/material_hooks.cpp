#include "material_hooks.hpp"

#include "brdf.hpp"

namespace rt {

MaterialHooks direct_lighting_materials() {
    MaterialHooks hooks;
    hooks.models["diffuse"].bsdf = [](const Material& m, bool, BsdfAtHit& at) -> const Bsdf& {
        return at.emplace<LambertBrdf>(m.albedo);
    };
    MaterialModel& mirror = hooks.models["mirror"];
    mirror.bsdf = [](const Material& m, bool, BsdfAtHit& at) -> const Bsdf& {
        return at.emplace<MirrorBrdf>(m.reflectance);
    };
    mirror.stand_in = [](const Material&, bool, BsdfAtHit& at) -> const Bsdf& {
        return at.emplace<MirrorBrdf>(Color(0));
    };
    mirror.stand_in_note = "shaded black (it shows only its emission)";
    hooks.models["glossy"].bsdf = [](const Material& m, bool, BsdfAtHit& at) -> const Bsdf& {
        return at.emplace<GlossyBrdf>(m.albedo, phong_exponent(m.roughness));
    };
    hooks.models["retroreflective"].bsdf = [](const Material& m, bool, BsdfAtHit& at) -> const Bsdf& {
        return at.emplace<RetroreflectiveBrdf>(m.albedo, phong_exponent(m.roughness));
    };
    return hooks;
}

}  // namespace rt
