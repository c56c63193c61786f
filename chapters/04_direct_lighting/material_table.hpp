// The material table: the one place where a render turns the scene's materials into what it simulates.
// Built once per render from the Scene and the simulated effects, it holds for every material
//   - its Bsdf seen from each side: outside (the side its shape's outward normal points to) and inside, so a
//     dielectric seen from inside has η = 1 / ior, and the path loops never ask which side they are on;
//   - its emission (one-sided: from the outside only);
//   - what fills the inside of its shapes (a Medium: chapter 07's Beer–Lambert absorption, chapter 09's
//     scattering media), if anything;
// and what fills the space between the shapes, where the camera is (chapter 09's fog), if anything.
// A material whose colour is a texture has it evaluated here, in bsdf(hit, at): the one place where a
// texture meets a BSDF, so every path loop that asks for the BSDF at a hit gets it.
// What a chapter cannot simulate gets a stand-in here, and only here, with a note for the run's summary:
//   a type without its effect simulated,  Lambert of its stand-in albedo (rt/io/material_kind.hpp: a glossy
//   or without a model in the hooks:      lobe's albedo, a dielectric's 0.73, a conductor's colour at
//                                         normal incidence), or its model's own stand-in (a mirror: black,
//                                         it shows only its emission);
//   a medium without "media":            inside a dielectric, the Beer–Lambert absorption of σ_a + σ_s (what
//                                        chapter 07's hook makes of it); between the shapes, empty space.
// Chapter 04 knows the four BRDFs; a later chapter adds what it simulates through MaterialHooks, so the table
// grows without this chapter including the later one.
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "02_intersection/hit.hpp"
#include "brdf.hpp"
#include "bsdf.hpp"
#include "bsdf_at_hit.hpp"
#include "material_hooks.hpp"
#include "medium.hpp"
#include "rt/core/effect_set.hpp"
#include "rt/core/scene.hpp"
#include "texture.hpp"

namespace rt {

class MaterialTable {
  public:
    MaterialTable(const Scene& scene, const EffectSet& simulated,
                  const MaterialHooks& hooks = direct_lighting_materials());

    // The BSDF at a hit on material m, from the side the ray came from (Hit::front_face).
    const Bsdf& bsdf(int material, bool front_face = true) const {
        return *sides_[2 * std::size_t(material) + (front_face ? 0 : 1)];
    }
    // The BSDF at `hit`, from the side the ray came from: bsdf(material, front_face), or for a textured
    // material the same BSDF with each textured colour parameter replaced by its texture at hit.uv, made in
    // `at` (valid while `at` is and until its next use).
    const Bsdf& bsdf(const Hit& hit, BsdfAtHit& at) const {
        const Textured* textured = textured_[std::size_t(hit.material)].get();
        return textured ? textured->at(hit, at) : bsdf(hit.material, hit.front_face);
    }
    // What the ray meets when it hits material m from that side: its emission, on the outside only unless
    // the material is two-sided.
    Color emission(int material, bool front_face) const {
        return front_face ? emission_[std::size_t(material)] : back_emission_[std::size_t(material)];
    }
    // The medium inside material m's shapes (null: nothing there, the ray travels unattenuated).
    const Medium* interior(int material) const { return interiors_[std::size_t(material)].get(); }
    // The medium between the shapes (null: empty space).
    const Medium* exterior() const { return exterior_.get(); }
    // One line per used material shaded by a stand-in: what it is shaded as, and the chapter that adds it.
    const std::vector<std::string>& notes() const { return notes_; }
    std::size_t size() const { return emission_.size(); }

  private:
    // A textured material: its textures, and how to make its BSDF with their colours.
    struct Textured {
        Material plain;  // the material without its name and textures: cheap to copy at each hit
        std::vector<std::pair<Color Material::*, Texture>> textures;
        MakeBsdf bsdf;

        const Bsdf& at(const Hit& hit, BsdfAtHit& room) const;
    };

    void add(const Material& m, bool used, const EffectSet& simulated, const MaterialHooks& hooks);

    std::deque<BsdfAtHit> owned_;                            // each material's BSDFs, made as a hit's are
    std::vector<std::unique_ptr<const Textured>> textured_;  // per material; null: constant colours
    std::vector<const Bsdf*> sides_;                         // 2 per material: outside, inside
    std::vector<Color> emission_;
    std::vector<Color> back_emission_;  // the emission of the back side: 0 unless the material is two-sided
    std::vector<std::unique_ptr<Medium>> interiors_;
    std::unique_ptr<Medium> exterior_;
    std::vector<std::string> notes_;
};

}  // namespace rt
