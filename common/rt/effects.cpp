#include "rt/effects.hpp"

#include <array>

namespace rt {
namespace {

// Whether light sampling can reach the material: a diffuse, glossy or retro-reflective lobe that reflects
// something, or rough glass (its microfacet lobes are not deltas; chapter 07).
bool reflects_diffusely(const Material& m) {
    if (m.type == MaterialType::kDielectric) return m.roughness > 0;
    const bool lobe = m.type == MaterialType::kDiffuse || m.type == MaterialType::kGlossy ||
                      m.type == MaterialType::kRetroreflective;
    return lobe && (m.albedo.r > 0 || m.albedo.g > 0 || m.albedo.b > 0);
}

}  // namespace

std::optional<Effect> effect_of(const Material& m) {
    switch (m.type) {
        case MaterialType::kDiffuse:
            return std::nullopt;
        case MaterialType::kMirror:
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
    const bool lights = !scene.point_lights.empty() || scene.environment || scene.has_area_lights();
    bool diffuse = false;
    for (const Shape& shape : scene.shapes) {
        const Material& m = scene.material_of(shape);
        diffuse = diffuse || reflects_diffusely(m);
        if (const auto effect = effect_of(m)) content.insert(*effect);
        // Glass reflects too (Fresnel): reflection rays.
        if (effect_of(m) == Effect::kRefraction) content.insert(Effect::kReflection);
        if (m.medium && m.medium->scatters()) content.insert(Effect::kMedia);
    }
    // No chapter before 09 has anything between the shapes: a medium there, even one that only absorbs,
    // calls for media.
    if (scene.medium) content.insert(Effect::kMedia);
    if (lights && diffuse) {
        content.insert(Effect::kShadows);
        content.insert(Effect::kDirect);
        content.insert(Effect::kIndirect);
    }
    return scene.effects ? content & *scene.effects : content;
}

std::string chapter_that_adds(Effect effect) {
    constexpr std::array<const char*, kEffectCount> kChapter = {"01", "03", "04", "05",
                                                                "04", "05", "07", "09"};
    return std::string("chapter ") + kChapter[std::size_t(effect)];
}

}  // namespace rt
