// A material type as the scene format knows it, whichever chapter renders it: its keys and how they are read,
// the effect that shades it as what it is, and the Lambert colour that stands in for it in a chapter that
// cannot simulate it. Every chapter loads every scene, so every type is known here; the chapter that teaches
// a type adds what it simulates (chapter 04's MaterialHooks) and chapter 11 what the shaders read. A new type
// is a MaterialKind and one register_material_kind() call, before the scene is loaded.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rt/core/effect_set.hpp"
#include "rt/core/scene.hpp"
#include "rt/io/scene_node.hpp"

namespace rt {

struct MaterialKind {
    std::string type;                    // as a scene's "type" spells it: "diffuse"
    std::vector<std::string_view> keys;  // every key it takes, "type" among them
    // Reads its keys into m (its name and type already set); every error one located line (Node::fail).
    void (*read)(const scene_reading::Node& node, const std::filesystem::path& scene_folder, Material& m);
    std::optional<Effect> effect;  // the effect that shades it as itself; none: a Lambert surface
    // The chapter that first simulates it, when it is not its effect's chapter ("07": a conductor's
    // reflection is chapter 05's, its Fresnel chapter 07's); empty otherwise.
    std::string first_chapter;
    // The albedo of the Lambert surface that stands in for it where it is not simulated.
    Color (*stand_in_albedo)(const Material& m);

    bool takes(std::string_view key) const;
};

// Adds a type (a type of that name already known is refused: std::logic_error).
void register_material_kind(MaterialKind kind);
// The kind of that name, or null; every type's name, in the order they were registered.
const MaterialKind* find_material_kind(std::string_view type);
std::vector<std::string_view> material_type_names();
// m's kind (a type nobody registered: std::logic_error; the loader refuses it first, with its place).
const MaterialKind& kind_of(const Material& m);
// What a chapter that cannot simulate m shades it as: Lambert of this albedo.
inline Color stand_in_albedo(const Material& m) {
    return kind_of(m).stand_in_albedo(m);
}

// The course's own types (course_materials.cpp): diffuse, mirror, glossy, retroreflective, dielectric,
// conductor, coateddiffuse, in that order.
std::vector<MaterialKind> course_material_kinds();

}  // namespace rt
