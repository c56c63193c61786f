#include "rt/io/scene_materials.hpp"

#include <array>
#include <memory>

#include "rt/core/enum_names.hpp"
#include "rt/io/input_file.hpp"
#include "rt/io/material_kind.hpp"
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
    Color least(kInfinity);
    for (const Color& t : desc.image->texels) {
        sum += Vec3d(t);
        least = glm::min(least, t);
    }
    const Color mean(sum / double(desc.image->texels.size()));
    return {desc, mean, least};
}

// A checker's squares are 1 / scale of a texture coordinate: the smallest that float, with its steps of 2^-24
// on coordinates near 1 (a quad's, a triangle's, a sphere's), still draws with 16 steps across.
constexpr Real kLargestCheckerScale = 1 << 20;

// Its colours are in [0, limit] (1 for a reflectance).
TextureDesc read_checker(const Node& node, double limit) {
    node.expect_object(std::array<std::string_view, 1>{"checker"}, "a checker texture");
    const Node checker = node["checker"];
    checker.expect_object(kCheckerKeys, "a checker");
    CheckerDesc desc;
    if (checker.has("even")) desc.even = checker["even"].color_in(limit);
    if (checker.has("odd")) desc.odd = checker["odd"].color_in(limit);
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
    return {desc, (desc.even + desc.odd) / Real(2), glm::min(desc.even, desc.odd)};
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

Color read_colour_parameter(const Node& node, const fs::path& scene_folder, Material& m,
                            Color Material::*parameter, double limit) {
    if (!node.json().is_object()) return m.*parameter = node.color_in(limit);
    TextureDesc texture;
    if (node.has("texture")) {
        texture = read_image_texture(node, scene_folder);
    } else if (node.has("checker")) {
        texture = read_checker(node, limit);
    } else {
        node.fail("must be [r, g, b] or a texture: {\"texture\": \"file.png\"} or {\"checker\": {...}}");
    }
    m.textures.push_back({parameter, texture});
    return m.*parameter = texture.mean;
}

Material read_material(const Node& node, const std::string& name, const fs::path& scene_folder) {
    if (!node.json().is_object()) node.fail("must be an object, got " + std::string(node.json().type_name()));
    const std::string type = node["type"].string();
    const MaterialKind* kind = find_material_kind(type);
    if (node.has("medium") && !(kind && kind->takes("medium"))) {
        node["medium"].fail("only a dielectric material holds a medium (its shapes' inside), got a " +
                            shown_name(type) + " material");
    }
    if (!kind) {
        const std::vector<std::string_view> names = material_type_names();
        std::string expected;
        for (std::size_t i = 0; i < names.size(); ++i)
            expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(names[i]);
        node["type"].fail("unknown material type " + quote(type) + suggestion(type, names) + "; expected " +
                          expected);
    }
    std::vector<std::string_view> keys = kind->keys;
    if (kind->takes("emission")) keys.push_back("two_sided");
    node.expect_object(keys, "a " + type + " material");
    Material m;
    m.name = name;
    m.type = type;
    kind->read(node, scene_folder, m);
    if (node.has("emission")) m.emission = node["emission"].color_in(kLargestNumber);
    if (node.has("two_sided")) {
        m.two_sided = node["two_sided"].boolean();
        if (m.two_sided && !m.emissive())
            node["two_sided"].fail("only an emitting material (emission above 0) is two-sided");
    }
    return m;
}

}  // namespace rt::scene_reading
