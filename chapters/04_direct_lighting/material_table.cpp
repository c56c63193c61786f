#include "material_table.hpp"

#include <cstdio>

#include "brdf.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/material_kind.hpp"

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

// How the table shades one material: its model (null: a stand-in), the BSDF it makes, and the note.
struct Shading {
    const MaterialModel* model = nullptr;
    MakeBsdf bsdf;
    bool two_sided = false;
    std::string note;
};

Shading lambert_stand_in(const Material& m, const std::string& why) {
    const auto lambert = [](const Material& at_hit, bool, BsdfAtHit& at) -> const Bsdf& {
        return at.emplace<LambertBrdf>(stand_in_albedo(at_hit));
    };
    return {nullptr, lambert, false,
            why + "; shaded as Lambert (albedo " + albedo_text(stand_in_albedo(m)) + ")"};
}

// The model of m's type when the hooks have one and the run simulates its effect; a stand-in otherwise, whose
// note names what is missing: the effect, the model, or for a type whose chapter comes after its effect's (a
// conductor), that chapter.
Shading shading_of(const Material& m, const EffectSet& simulated, const MaterialHooks& hooks) {
    const MaterialKind& kind = kind_of(m);
    const auto found = hooks.models.find(m.type);
    const MaterialModel* model = found == hooks.models.end() ? nullptr : &found->second;
    const bool effect_simulated = !kind.effect || simulated.contains(*kind.effect);
    if (model && effect_simulated) return {model, model->bsdf, model->two_sided, ""};
    if (!model && !kind.first_chapter.empty()) return lambert_stand_in(m, simulated_from(m));
    const std::string why = effect_simulated ? "no chapter of this run simulates it" : skipped(*kind.effect);
    if (model && model->stand_in) return {nullptr, model->stand_in, false, why + "; " + model->stand_in_note};
    return lambert_stand_in(m, why);
}

// What fills the shapes of a material its model simulates: the scene's medium with media simulated, or what
// the model makes of it without (a scattering medium's note then says so).
std::unique_ptr<Medium> interior_of(const Material& m, const Shading& shading, bool media,
                                    const MaterialHooks& hooks, std::string& note) {
    if (!shading.model) return nullptr;
    if (m.medium && media) return hooks.medium(*m.medium);
    if (!shading.model->interior) return nullptr;
    if (m.medium && m.medium->scatters()) {
        note = "its medium: " + skipped(Effect::kMedia) +
               "; treated as Beer-Lambert absorption by sigma_a + sigma_s";
    }
    return shading.model->interior(m);
}

}  // namespace

const Bsdf& MaterialTable::Textured::at(const Hit& hit, BsdfAtHit& room) const {
    Material here = plain;
    for (const auto& [parameter, texture] : textures) here.*parameter = texture.at(hit.uv);
    return bsdf(here, hit.front_face, room);
}

MaterialTable::MaterialTable(const Scene& scene, const EffectSet& simulated, const MaterialHooks& hooks) {
    const std::vector<bool> used = scene.used_materials();
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        add(scene.materials[i], used[i], simulated, hooks);
    if (scene.medium) {
        if (simulated.contains(Effect::kMedia) && hooks.medium) {
            exterior_ = hooks.medium(*scene.medium);
        } else {
            notes_.push_back("medium between the shapes: " + skipped(Effect::kMedia) +
                             "; treated as empty space");
        }
    }
}

void MaterialTable::add(const Material& m, bool used, const EffectSet& simulated,
                        const MaterialHooks& hooks) {
    const Shading shading = shading_of(m, simulated, hooks);
    std::string note = shading.note;
    const bool media = simulated.contains(Effect::kMedia) && hooks.medium;
    interiors_.push_back(interior_of(m, shading, media, hooks, note));
    const Bsdf& outside = shading.bsdf(m, true, owned_.emplace_back());
    sides_.push_back(&outside);
    sides_.push_back(shading.two_sided ? &shading.bsdf(m, false, owned_.emplace_back()) : &outside);
    emission_.push_back(m.emission);
    back_emission_.push_back(m.two_sided ? m.emission : Color(0));
    std::unique_ptr<Textured> textured;
    if (!m.textures.empty()) {
        textured = std::make_unique<Textured>(Textured{m, {}, shading.bsdf});
        textured->plain.name.clear();
        textured->plain.textures.clear();
        for (const Material::Textured& t : m.textures)
            textured->textures.emplace_back(t.parameter, Texture(t.texture));
    }
    textured_.push_back(std::move(textured));
    if (used && !note.empty()) notes_.push_back(m.type + " material '" + m.name + "': " + note);
}

}  // namespace rt
