#include "rt/core/effects.hpp"

#include <array>
#include <variant>

namespace rt {
namespace {

// Whether a light shining on the material is seen again: a diffuse, glossy or retro-reflective lobe or a
// mirror that reflects something, and every dielectric (Fresnel reflects some of any light, a medium inside
// may scatter it, and a chapter without refraction shades it as a grey stand-in). Mirrors and smooth glass
// count although the path loop samples no light at their delta vertices: chapters 03 and 04 shade them as
// Lambert stand-ins, which light does reach.
bool lit_by_lights(const Material& m) {
    if (m.type == MaterialType::kDielectric) return true;
    if (m.type == MaterialType::kConductor) return !is_black(m.stand_in_albedo());  // F(0°) > 0
    const Color reflects = m.type == MaterialType::kMirror ? m.reflectance : m.albedo;
    return reflects.r > 0 || reflects.g > 0 || reflects.b > 0;
}

}  // namespace

std::optional<Effect> effect_of(const Material& m) {
    switch (m.type) {
        case MaterialType::kDiffuse:
            return std::nullopt;
        case MaterialType::kMirror:
        case MaterialType::kConductor:
            return Effect::kReflection;
        case MaterialType::kGlossy:
        case MaterialType::kRetroreflective:
            return Effect::kGlossy;
        case MaterialType::kDielectric:
            return Effect::kRefraction;
    }
    return std::nullopt;
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
    if (m.type == MaterialType::kConductor) return "a conductor is simulated from chapter 07 on";
    const auto effect = effect_of(m);
    if (!effect) return "it is simulated from chapter 01 on";
    return std::string(kEffectNames[std::size_t(*effect)]) + " is simulated from " +
           chapter_that_adds(*effect) + " on";
}

}  // namespace rt
