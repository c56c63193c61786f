// The course's own material types as the scene format reads them (assets/scenes/README.md, "materials"): each
// one's keys, its parameters and their limits, its effect and its stand-in. Chapter 04 simulates the first
// four, chapter 07 dielectrics, conductors and coated diffuse surfaces.
#include "rt/core/conductor_presets.hpp"
#include "rt/io/material_kind.hpp"
#include "rt/io/scene_materials.hpp"

namespace rt {
namespace {

using scene_reading::kLargestNumber;
using scene_reading::Node;
namespace fs = std::filesystem;

// What a dielectric is shaded as before chapter 07: a light grey.
constexpr Real kDielectricStandIn = Real(0.73);

Color albedo_of(const Material& m) {
    return m.albedo;
}

// A lobe's width: in (0, 1] (0 would be a delta).
void read_lobe(const Node& node, const fs::path& folder, Material& m) {
    if (node.has("albedo")) read_colour_parameter(node["albedo"], folder, m, &Material::albedo);
    if (node.has("roughness")) m.roughness = node["roughness"].real_in(0, 1, true, false);
}

MaterialKind diffuse() {
    const auto read = [](const Node& node, const fs::path& folder, Material& m) {
        if (node.has("albedo")) read_colour_parameter(node["albedo"], folder, m, &Material::albedo);
    };
    return {"diffuse", {"type", "albedo", "emission"}, read, std::nullopt, "", albedo_of};
}

MaterialKind mirror() {
    const auto read = [](const Node& node, const fs::path& folder, Material& m) {
        if (node.has("reflectance"))
            read_colour_parameter(node["reflectance"], folder, m, &Material::reflectance);
    };
    const auto reflectance = [](const Material& m) { return m.reflectance; };
    return {"mirror", {"type", "reflectance", "emission"}, read, Effect::kReflection, "", reflectance};
}

MaterialKind glossy(const char* type) {
    return {type, {"type", "albedo", "roughness", "emission"}, read_lobe, Effect::kGlossy, "", albedo_of};
}

MaterialKind dielectric() {
    const auto read = [](const Node& node, const fs::path&, Material& m) {
        if (node.has("absorption") && node.has("medium"))
            node["medium"].fail("give either absorption or medium (a medium's sigma_a is its absorption)");
        m.roughness = 0;  // smooth unless the file says otherwise
        if (node.has("roughness")) m.roughness = node["roughness"].real_in(0, 1, true, false);
        if (node.has("ior")) m.ior = node["ior"].real_in(1, 10, false, false);
        if (node.has("absorption")) m.absorption = node["absorption"].color_in(kLargestNumber);
        if (node.has("medium")) m.medium = scene_reading::read_medium(node["medium"]);
    };
    const auto grey = [](const Material&) { return Color(kDielectricStandIn); };
    return {"dielectric", {"type", "ior", "absorption", "roughness", "medium"}, read, Effect::kRefraction, "",
            grey};
}

// A conductor's complex index η + i k: a named preset (conductor_presets.hpp), or both "eta" and "k", each
// >= 0 per channel (or a texture of such colours) and not both 0 in a channel anywhere (an index of 0
// refracts nothing and divides by zero).
void read_conductor_index(const Node& node, const fs::path& folder, Material& m) {
    if (node.has("preset")) {
        const Node preset = node["preset"];
        if (node.has("eta") || node.has("k")) preset.fail("give either a preset or eta and k, not both");
        const std::string name = preset.string();
        for (const ConductorPreset& p : kConductorPresets) {
            if (p.name == name) {
                m.eta = p.eta;
                m.k = p.k;
                return;
            }
        }
        preset.fail("unknown conductor preset " + scene_reading::quote(name) +
                    scene_reading::suggestion(name, kConductorPresetNames) +
                    "; expected gold, copper or aluminium");
    }
    if (!node.has("eta") && !node.has("k")) node.fail("a conductor needs eta and k, or a preset");
    Color least_eta = read_colour_parameter(node["eta"], folder, m, &Material::eta, kLargestNumber);
    Color least_k = read_colour_parameter(node["k"], folder, m, &Material::k, kLargestNumber);
    for (const Material::Textured& t : m.textures)
        (t.parameter == &Material::eta ? least_eta : least_k) = t.texture.least;
    for (int i = 0; i < 3; ++i) {
        if (least_eta[i] == 0 && least_k[i] == 0) {
            const Node eta = node["eta"];
            (eta.json().is_array() ? eta.element(std::size_t(i)) : eta)
                .fail("eta and k must not both be 0 in a channel");
        }
    }
}

MaterialKind conductor() {
    const auto read = [](const Node& node, const fs::path& folder, Material& m) {
        read_conductor_index(node, folder, m);
        m.roughness = 0;  // smooth unless the file says otherwise; 0 is a smooth metal, not a delta lobe
        if (node.has("roughness")) m.roughness = node["roughness"].real_in(0, 1, false, false);
    };
    // Its reflectance at normal incidence, F(0°) = ((η − 1)² + k²) / ((η + 1)² + k²) (chapter 07's
    // fresnel_conductor at cos θ = 1; a test holds the two equal).
    const auto f0 = [](const Material& m) {
        const Color below = m.eta - Color(1), above = m.eta + Color(1), k2 = m.k * m.k;
        return (below * below + k2) / (above * above + k2);
    };
    return {"conductor", {"type", "eta", "k", "preset", "roughness", "emission"},
            read,        Effect::kReflection,
            "07",        f0};
}

// A Lambert base of reflectance "albedo" under a smooth clear coat of index "ior" (chapter 07's
// coated_diffuse.hpp): its coat is a mirror (reflection). Before chapter 07 it is Lambert of what it
// reflects at normal incidence: the coat's F(0°) = ((η − 1) / (η + 1))², and the base's colour through it,
// (1 − F(0°)) albedo (a black base still reflects its coat's few per cent).
MaterialKind coated_diffuse() {
    const auto read = [](const Node& node, const fs::path& folder, Material& m) {
        if (node.has("albedo")) read_colour_parameter(node["albedo"], folder, m, &Material::albedo);
        if (node.has("ior")) m.ior = node["ior"].real_in(1, 10, false, false);
    };
    const auto coat_and_base = [](const Material& m) {
        const Real f0 = (m.ior - 1) * (m.ior - 1) / ((m.ior + 1) * (m.ior + 1));
        return Color(f0) + (1 - f0) * m.albedo;
    };
    return {"coateddiffuse", {"type", "albedo", "ior", "emission"}, read, Effect::kReflection, "07",
            coat_and_base};
}

}  // namespace

std::vector<MaterialKind> course_material_kinds() {
    return {diffuse(),    mirror(),    glossy("glossy"), glossy("retroreflective"),
            dielectric(), conductor(), coated_diffuse()};
}

}  // namespace rt
