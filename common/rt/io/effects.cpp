#include "rt/io/effects.hpp"

#include <array>
#include <variant>

#include "rt/io/material_kind.hpp"

namespace rt {
namespace {

// Whether a light shining on the material is seen again: a surface that reflects or transmits something.
// Its stand-in's albedo says so for every type: a lobe's albedo, a mirror's reflectance, a conductor's F(0°),
// a dielectric's grey (Fresnel reflects some of any light, a medium inside may scatter it). Mirrors and
// smooth glass count although the path loop samples no light at their delta vertices: chapters 03 and 04
// shade them as Lambert stand-ins, which light does reach.
bool lit_by_lights(const Material& m) {
    return !is_black(stand_in_albedo(m));
}

}  // namespace

std::optional<Effect> effect_of(const Material& m) {
    return kind_of(m).effect;
}

EffectSet needed(const Scene& scene) {
    EffectSet content{Effect::kCameraRays};
    const bool lights = scene.has_lights();
    // Anything lights can shine on: a surface that reflects or transmits their light, or a medium that
    // scatters it (its light arrives only by scattering: without shadows, direct and indirect it stays
    // black). Only dielectrics hold a medium, and every dielectric counts.
    bool lit = scene.medium && scene.medium->scatters();
    for (const Shape& shape : scene.shapes) {
        const Material& m = scene.material_of(shape);
        lit = lit || lit_by_lights(m);
        if (const auto effect = effect_of(m)) content.insert(*effect);
        // Glass reflects too (Fresnel): reflection rays.
        if (effect_of(m) == Effect::kRefraction) content.insert(Effect::kReflection);
        if (m.medium && m.medium->scatters()) content.insert(Effect::kMedia);
        const auto* mesh = std::get_if<MeshShape>(&shape.geometry);
        if (mesh && mesh->smooth()) content.insert(Effect::kShadingNormals);
    }
    // No chapter before 09 has anything between the shapes: a medium there, even one that only absorbs,
    // calls for media.
    if (scene.medium) content.insert(Effect::kMedia);
    if (lights && lit) {
        content.insert(Effect::kShadows);
        content.insert(Effect::kDirect);
        content.insert(Effect::kIndirect);
    }
    return scene.effects ? content & *scene.effects : content;
}

EffectSet simulated_effects(const Scene& scene, const EffectSet& supported) {
    return needed(scene) & supported;
}

std::string chapter_that_adds(Effect effect) {
    constexpr std::array<const char*, kEffectCount> kChapter = {"01", "03", "04", "05", "04",
                                                                "05", "07", "09", "04"};
    return std::string("chapter ") + kChapter[std::size_t(effect)];
}

std::string simulated_from(const Material& m) {
    const MaterialKind& kind = kind_of(m);
    if (!kind.first_chapter.empty())
        return "a " + kind.type + " is simulated from chapter " + kind.first_chapter + " on";
    const auto effect = kind.effect;
    if (!effect) return "it is simulated from chapter 01 on";
    return std::string(kEffectNames[std::size_t(*effect)]) + " is simulated from " +
           chapter_that_adds(*effect) + " on";
}

}  // namespace rt
