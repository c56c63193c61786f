// How a chapter simulates the material types it teaches: for each type of the scene format (its MaterialKind,
// rt/io/material_kind.hpp), by name, the model that makes its BSDF. Chapter 04 gives its four BRDFs
// (direct_lighting_materials); chapter 07 adds dielectrics and conductors, chapter 09 media, each to the
// hooks of the chapter before, so the material table grows without this chapter including a later one. A type
// without a model here is shaded by a stand-in (material_table.hpp).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>

#include "bsdf.hpp"
#include "bsdf_at_hit.hpp"
#include "medium.hpp"
#include "rt/core/scene.hpp"

namespace rt {

// Makes material m's BSDF in `at`, as seen from outside its shapes (true) or from inside; its colour
// parameters are those of m, which for a textured material at a hit are the textures' values there.
using MakeBsdf = std::function<const Bsdf&(const Material& m, bool outside, BsdfAtHit& at)>;

struct MaterialModel {
    MakeBsdf bsdf;
    bool two_sided = false;  // whether its BSDF from inside differs (a dielectric's η is 1 / ior there)
    // What fills its shapes when media are not simulated (chapter 07's Beer–Lambert absorption), if anything.
    std::function<std::unique_ptr<Medium>(const Material&)> interior;
    // What stands in for it when its effect is not simulated, and what the note says of it; none: a Lambert
    // surface of its stand-in albedo.
    MakeBsdf stand_in;
    std::string stand_in_note;
};

struct MaterialHooks {
    std::map<std::string, MaterialModel, std::less<>> models;  // by type, as the scene spells it
    // With media simulated (chapter 09): the medium a scene's "medium" describes, inside a dielectric or
    // between the shapes.
    std::function<std::unique_ptr<Medium>(const MediumDesc&)> medium;
};

// Chapter 04's models: diffuse, mirror, glossy and retroreflective (brdf.hpp).
MaterialHooks direct_lighting_materials();

}  // namespace rt
