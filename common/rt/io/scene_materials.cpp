#include "rt/io/scene_materials.hpp"

#include <array>
#include <memory>

#include "rt/core/conductor_presets.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/io/input_file.hpp"
#include "rt/io/texture_image.hpp"

namespace rt::scene_reading {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kMediumKeys[] = {"sigma_a", "sigma_s", "g"};
constexpr std::string_view kImageTextureKeys[] = {"texture", "scale", "wrap", "filter", "encoding"};
constexpr std::string_view kCheckerKeys[] = {"even", "odd", "scale"};

// A value that is one of an enum's names (a texture's "wrap", "filter" or "encoding").
template <NamedEnum E>
E read_enum(const Node& node) {
    const std::string value = node.string();
    std::vector<std::string_view> names;
    for (const EnumName<E>& entry : names_of(E{}).names) {
        if (entry.name == value) return entry.value;
        names.push_back(entry.name);
    }
    node.fail("unknown value " + quote(value) + suggestion(value, names) + "; expected " +
              joined_names<E>(", ", " or "));
}

// {"texture": file, "scale": [su, sv], "wrap": ..., "filter": ..., "encoding": ...}: the image is read here,
// once, relative to the scene's folder as a mesh is.
TextureDesc read_image_texture(const Node& node, const fs::path& scene_folder) {
    node.expect_object(kImageTextureKeys, "an image texture");
    ImageTextureDesc desc;
    const Node file = node["texture"];
    desc.file = file.string();
    if (node.has("scale")) {
        const Node scale = node["scale"];
        if (scale.array_size() != 2)
            scale.fail("must be an array of 2 numbers, got " + std::to_string(scale.array_size()));
        desc.scale = {scale.element(0).positive(), scale.element(1).positive()};
    }
    if (node.has("wrap")) desc.wrap = read_enum<TextureWrap>(node["wrap"]);
    if (node.has("filter")) desc.filter = read_enum<TextureFilter>(node["filter"]);
    const bool srgb =
        !node.has("encoding") || read_enum<TextureEncoding>(node["encoding"]) == TextureEncoding::kSrgb;
    const fs::path path = scene_folder / desc.file;
    try {
        desc.image = std::make_shared<const TextureImage>(read_texture_image(path, srgb));
    } catch (const InputError& e) {
        file.fail(shown(path) + ": " + e.what());
    }
    Vec3d sum(0);
    for (const Color& t : desc.image->texels) sum += Vec3d(t);
    const Color mean(sum / double(desc.image->texels.size()));
    return {desc, mean};
}

// A checker's squares are 1 / scale of a texture coordinate: the smallest that float, with its steps of 2^-24
// on coordinates near 1 (a quad's, a triangle's, a sphere's), still draws with 16 steps across.
constexpr Real kLargestCheckerScale = 1 << 20;

TextureDesc read_checker(const Node& node) {
    node.expect_object(std::array<std::string_view, 1>{"checker"}, "a checker texture");
    const Node checker = node["checker"];
    checker.expect_object(kCheckerKeys, "a checker");
    CheckerDesc desc;
    if (checker.has("even")) desc.even = checker["even"].color_in(1);
    if (checker.has("odd")) desc.odd = checker["odd"].color_in(1);
    if (checker.has("scale")) {
        const Node scale = checker["scale"];
        desc.scale = scale.positive();
        if (desc.scale > kLargestCheckerScale) {
            scale.fail(
                "must be at most 1048576 (2^20: float resolves coordinates near 1 to 2^-24, 16 steps "
                "a square), got " +
                show(desc.scale));
        }
    }
    return {desc, (desc.even + desc.odd) / Real(2)};
}

// A colour parameter (albedo, reflectance): [r, g, b] in [0, 1], or a texture, whose mean is the colour.
Color read_colour_parameter(const Node& node, const fs::path& scene_folder,
                            std::optional<TextureDesc>& texture) {
    if (!node.json().is_object()) return node.color_in(1);
    if (node.has("texture")) {
        texture = read_image_texture(node, scene_folder);
    } else if (node.has("checker")) {
        texture = read_checker(node);
    } else {
        node.fail("must be [r, g, b] or a texture: {\"texture\": \"file.png\"} or {\"checker\": {...}}");
    }
    return texture->mean;
}

// A conductor's complex index η + i k: a named preset (conductor_presets.hpp), or both "eta" and "k", each
// >= 0 per channel and not both 0 in a channel (an index of 0 refracts nothing and divides by zero).
void read_conductor_index(const Node& node, Material& m) {
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
        preset.fail("unknown conductor preset " + quote(name) + suggestion(name, kConductorPresetNames) +
                    "; expected gold, copper or aluminium");
    }
    if (!node.has("eta") && !node.has("k")) node.fail("a conductor needs eta and k, or a preset");
    m.eta = node["eta"].color_in(kLargestNumber);
    m.k = node["k"].color_in(kLargestNumber);
    for (int i = 0; i < 3; ++i) {
        if (m.eta[i] == 0 && m.k[i] == 0) {
            node["eta"].element(std::size_t(i)).fail("eta and k must not both be 0 in a channel");
        }
    }
}

}  // namespace

MediumDesc read_medium(const Node& node) {
    node.expect_object(kMediumKeys, "a medium");
    MediumDesc medium;
    if (node.has("sigma_a")) medium.sigma_a = node["sigma_a"].color_in(kLargestNumber);
    if (node.has("sigma_s")) medium.sigma_s = node["sigma_s"].color_in(kLargestNumber);
    if (node.has("g")) medium.g = node["g"].real_in(-1, 1, true, true);
    return medium;
}

Material read_material(const Node& node, const std::string& name, const fs::path& scene_folder) {
    if (!node.json().is_object()) node.fail("must be an object, got " + std::string(node.json().type_name()));
    const std::string type = node["type"].string();
    if (type != "dielectric" && node.has("medium")) {
        node["medium"].fail("only a dielectric material holds a medium (its shapes' inside), got a " +
                            shown_name(type) + " material");
    }
    Material m;
    m.name = name;
    if (type == "diffuse") {
        m.type = MaterialType::kDiffuse;
        node.expect_object(std::array<std::string_view, 3>{"type", "albedo", "emission"},
                           "a diffuse material");
    } else if (type == "mirror") {
        m.type = MaterialType::kMirror;
        node.expect_object(std::array<std::string_view, 3>{"type", "reflectance", "emission"},
                           "a mirror material");
    } else if (type == "glossy" || type == "retroreflective") {
        m.type = type == "glossy" ? MaterialType::kGlossy : MaterialType::kRetroreflective;
        node.expect_object(std::array<std::string_view, 4>{"type", "albedo", "roughness", "emission"},
                           "a " + type + " material");
    } else if (type == "dielectric") {
        m.type = MaterialType::kDielectric;
        m.roughness = 0;  // smooth unless the file says otherwise
        node.expect_object(std::array<std::string_view, 5>{"type", "ior", "absorption", "roughness", "medium"},
                           "a dielectric material");
        if (node.has("absorption") && node.has("medium")) {
            node["medium"].fail("give either absorption or medium (a medium's sigma_a is its absorption)");
        }
    } else if (type == "conductor") {
        m.type = MaterialType::kConductor;
        m.roughness = 0;  // smooth unless the file says otherwise
        node.expect_object(
            std::array<std::string_view, 6>{"type", "eta", "k", "preset", "roughness", "emission"},
            "a conductor material");
        read_conductor_index(node, m);
    } else {
        node["type"].fail("unknown material type " + quote(type) + suggestion(type, kMaterialTypeNames) +
                          "; expected diffuse, mirror, glossy, retroreflective, dielectric or conductor");
    }
    if (node.has("albedo")) m.albedo = read_colour_parameter(node["albedo"], scene_folder, m.texture);
    if (node.has("reflectance"))
        m.reflectance = read_colour_parameter(node["reflectance"], scene_folder, m.texture);
    if (node.has("emission")) m.emission = node["emission"].color_in(kLargestNumber);
    // A conductor's roughness may be 0, a smooth metal; a lobe's may not (it would be a delta).
    if (node.has("roughness"))
        m.roughness = node["roughness"].real_in(0, 1, m.type != MaterialType::kConductor, false);
    if (node.has("ior")) m.ior = node["ior"].real_in(1, 10, false, false);
    if (node.has("absorption")) m.absorption = node["absorption"].color_in(kLargestNumber);
    if (node.has("medium")) m.medium = read_medium(node["medium"]);
    return m;
}

}  // namespace rt::scene_reading
