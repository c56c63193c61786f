#include "material_table.hpp"

#include <cstdio>
#include <type_traits>

#include "brdf.hpp"
#include "rt/core/effects.hpp"

namespace rt {
namespace {

std::string albedo_text(const Color& albedo) {
    char text[64];
    std::snprintf(text, sizeof text, "%.2g", double(luminance(albedo)));
    return text;
}

std::string skipped(Effect effect) {
    return std::string(kEffectNames[std::size_t(effect)]) + " is not simulated in this run (" +
           chapter_that_adds(effect) + " adds it)";
}

// The BSDF of the material's type (B) with `colour` in place of its own: what the texture gives at a hit.
template <class B>
const Bsdf& recolour(const Bsdf& own, const Color& colour, BsdfAtHit& at) {
    if constexpr (std::is_same_v<B, LambertBrdf> || std::is_same_v<B, MirrorBrdf>) {
        return at.emplace<B>(colour);
    } else {
        return at.emplace<B>(colour, static_cast<const B&>(own).exponent);
    }
}

}  // namespace

MaterialTable::MaterialTable(const Scene& scene, const EffectSet& simulated, const MaterialHooks& hooks) {
    const std::vector<bool> used = scene.used_materials();
    const bool refraction = simulated.contains(Effect::kRefraction) && hooks.dielectric;
    const bool media = simulated.contains(Effect::kMedia) && hooks.medium;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        emission_.push_back(m.emission);
        std::unique_ptr<Medium> interior;
        std::unique_ptr<Bsdf> outside, inside;
        std::string note;
        const Bsdf& (*recoloured)(const Bsdf&, const Color&, BsdfAtHit&) = nullptr;  // for a texture
        const auto lambert_stand_in = [&](const std::string& why) {
            outside = std::make_unique<LambertBrdf>(m.stand_in_albedo());
            recoloured = recolour<LambertBrdf>;
            note = why + "; shaded as Lambert (albedo " + albedo_text(m.stand_in_albedo()) + ")";
        };
        switch (m.type) {
            case MaterialType::kDiffuse:
                outside = std::make_unique<LambertBrdf>(m.albedo);
                recoloured = recolour<LambertBrdf>;
                break;
            case MaterialType::kMirror:
                if (simulated.contains(Effect::kReflection)) {
                    outside = std::make_unique<MirrorBrdf>(m.reflectance);
                    recoloured = recolour<MirrorBrdf>;
                } else {
                    outside = std::make_unique<MirrorBrdf>(Color(0));
                    note = skipped(Effect::kReflection) + "; shaded black (it shows only its emission)";
                }
                break;
            case MaterialType::kGlossy:
            case MaterialType::kRetroreflective:
                if (!simulated.contains(Effect::kGlossy)) {
                    lambert_stand_in(skipped(Effect::kGlossy));
                } else if (m.type == MaterialType::kGlossy) {
                    outside = std::make_unique<GlossyBrdf>(m.albedo, phong_exponent(m.roughness));
                    recoloured = recolour<GlossyBrdf>;
                } else {
                    outside = std::make_unique<RetroreflectiveBrdf>(m.albedo, phong_exponent(m.roughness));
                    recoloured = recolour<RetroreflectiveBrdf>;
                }
                break;
            case MaterialType::kConductor:
                if (!hooks.conductor) {
                    lambert_stand_in(simulated_from(m));
                } else if (!simulated.contains(Effect::kReflection)) {
                    lambert_stand_in(skipped(Effect::kReflection));
                } else {
                    outside = hooks.conductor(m);
                }
                break;
            case MaterialType::kDielectric:
                if (refraction) {
                    outside = hooks.dielectric(m, true);
                    inside = hooks.dielectric(m, false);
                    if (m.medium && media) {
                        interior = hooks.medium(*m.medium);
                    } else if (hooks.dielectric_interior) {
                        interior = hooks.dielectric_interior(m);
                        if (m.medium && m.medium->scatters()) {
                            note = "its medium: " + skipped(Effect::kMedia) +
                                   "; treated as Beer-Lambert absorption by sigma_a + sigma_s";
                        }
                    }
                } else {
                    lambert_stand_in(skipped(Effect::kRefraction));
                }
                break;
        }
        const Bsdf* out = outside.get();
        const Bsdf* in = inside ? inside.get() : out;  // a reflector looks the same from both sides
        owned_.push_back(std::move(outside));
        if (inside) owned_.push_back(std::move(inside));
        sides_.push_back(out);
        sides_.push_back(in);
        interiors_.push_back(std::move(interior));
        textured_.push_back(m.texture && recoloured ? std::make_unique<const TexturedColour>(
                                                          TexturedColour{Texture(*m.texture), recoloured})
                                                    : nullptr);
        if (used[i] && !note.empty()) {
            notes_.push_back(std::string(kMaterialTypeNames[std::size_t(m.type)]) + " material '" + m.name +
                             "': " + note);
        }
    }
    if (scene.medium) {
        if (media) {
            exterior_ = hooks.medium(*scene.medium);
        } else {
            notes_.push_back("medium between the shapes: " + skipped(Effect::kMedia) +
                             "; treated as empty space");
        }
    }
}

}  // namespace rt
