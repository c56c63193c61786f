#include "rt/io/scene_loader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "rt/core/conductor_presets.hpp"
#include "rt/core/did_you_mean.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/core/errors.hpp"
#include "rt/core/image.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/environment_image.hpp"
#include "rt/io/input_file.hpp"
#include "rt/io/json_reader.hpp"
#include "rt/io/obj_parser.hpp"
#include "rt/io/ply_parser.hpp"
#include "rt/io/texture_image.hpp"

namespace rt {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr double kLargestNumber = kLargestSceneNumber;
constexpr const char* kRealName = sizeof(Real) == sizeof(float) ? "float" : "double";

std::string show(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
}

// A name from the file in a message: escaped so that the message stays one line (printable.hpp), and cut
// after 64 bytes.
std::string shown_name(std::string_view s) {
    return printable(s, 64);
}

std::string quote(std::string_view s) {
    return "\"" + shown_name(s) + "\"";
}

// A number written with a fraction or an exponent, shown as one: 32.0 stays "32.0", not "32".
std::string show_fraction(double x) {
    std::string text = show(x);
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
}

std::string show(const Vec3& v) {
    return "[" + show(v.x) + ", " + show(v.y) + ", " + show(v.z) + "]";
}

// A vector that float arithmetic can normalise: its length in Real is positive and finite.
bool normalisable(const Vec3& v) {
    const Real length = glm::length(v);
    return length > 0 && std::isfinite(length) && is_finite(v / length);
}

std::string suggestion(std::string_view word, std::span<const std::string_view> candidates) {
    const auto match = closest_match(word, candidates);
    return match ? " (did you mean " + quote(*match) + "?)" : "";
}

// A value in the scene file and its place ("shapes[3].radius"); every read checks type and range.
class Node {
  public:
    Node(const Json& value, std::string place, const std::string& file)
        : value_(value), place_(std::move(place)), file_(file) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(file_ + ": " + (place_.empty() ? "" : place_ + ": ") + what);
    }
    const std::string& place() const { return place_; }
    const Json& json() const { return value_; }

    bool has(const char* key) const { return value_.contains(key); }
    Node operator[](const char* key) const {
        if (!value_.contains(key)) fail("missing required field " + quote(key));
        return Node(value_.at(key), child_place(key), file_);
    }
    Node element(std::size_t i) const {
        return Node(value_.at(i), place_ + "[" + std::to_string(i) + "]", file_);
    }

    // `owner` says whose keys these are in the message ("a mirror material"), when the type decides them.
    void expect_object(std::span<const std::string_view> allowed_keys, const std::string& owner = "") const {
        if (!value_.is_object()) fail("must be an object, got " + std::string(value_.type_name()));
        for (const auto& [key, unused] : value_.items()) {
            bool known = false;
            for (std::string_view k : allowed_keys) known = known || k == key;
            if (!known) {
                throw InputError(file_ + ": " + child_place(key) + ": unknown key" +
                                 (owner.empty() ? "" : " for " + owner) + suggestion(key, allowed_keys));
            }
        }
    }
    std::size_t array_size() const {
        if (!value_.is_array()) fail("must be an array, got " + std::string(value_.type_name()));
        return value_.size();
    }
    std::string string() const {
        if (!value_.is_string()) fail("must be a string, got " + std::string(value_.type_name()));
        return value_.get<std::string>();
    }
    double number() const {
        if (!value_.is_number()) fail("must be a number, got " + std::string(value_.type_name()));
        const double x = value_.get<double>();
        if (!std::isfinite(x) || std::abs(x) > kLargestNumber) {
            fail("must be a finite number of magnitude at most " + show(kLargestNumber) + ", got " + show(x));
        }
        return x;
    }
    Real real() const { return Real(number()); }
    // The range is checked on the value as it will be used, in Real: 179.99999999 is 180 in float, and 1e-50
    // is 0.
    Real real_in(double low, double high, bool low_open, bool high_open) const {
        const double x = number();
        const double r = double(Real(x));
        if ((low_open ? r <= low : r < low) || (high_open ? r >= high : r > high)) {
            fail("must be in " + std::string(low_open ? "(" : "[") + show(low) + ", " + show(high) +
                 (high_open ? ")" : "]") + ", got " + as_used(x));
        }
        return Real(x);
    }
    Real positive() const {
        const double x = number();
        if (!(Real(x) > 0)) fail("must be > 0, got " + as_used(x));
        return Real(x);
    }
    int integer(long long low, long long high) const {
        const std::string range = "[" + std::to_string(low) + ", " + std::to_string(high) + "]";
        if (!value_.is_number_integer()) {
            fail("must be a whole number in " + range + ", got " +
                 (value_.is_number() ? show_fraction(value_.get<double>()) : std::string(value_.type_name())));
        }
        if (value_.is_number_unsigned() &&
            value_.get<unsigned long long>() > static_cast<unsigned long long>(high)) {
            fail("must be in " + range + ", got " + std::to_string(value_.get<unsigned long long>()));
        }
        const long long x = value_.get<long long>();
        if (x < low || x > high) fail("must be in " + range + ", got " + std::to_string(x));
        return int(x);
    }
    Vec3 vec3() const {
        if (!value_.is_array() || value_.size() != 3) {
            fail("must be an array of 3 numbers, got " + (value_.is_array()
                                                              ? "an array of " + std::to_string(value_.size())
                                                              : std::string(value_.type_name())));
        }
        return {element(0).real(), element(1).real(), element(2).real()};
    }
    // A direction: float must be able to normalise it (not zero, not so short that its length underflows).
    Vec3 direction() const {
        const Vec3 v = vec3();
        if (!normalisable(v)) fail("must be a direction of non-zero length, got " + show(v));
        return v;
    }
    Color color_in(double high) const {
        const Vec3 c = vec3();
        for (int i = 0; i < 3; ++i) {
            if (c[i] < 0 || c[i] > high) {
                element(std::size_t(i)).fail("must be in [0, " + show(high) + "], got " + show(c[i]));
            }
        }
        return c;
    }

  private:
    // The value as given, and what Real makes of it when that differs: "1e-50, which is 0 in float".
    static std::string as_used(double x) {
        if (double(Real(x)) == x) return show(x);
        char text[32];
        const auto end = std::to_chars(text, text + sizeof text, x).ptr;  // the shortest exact form
        return std::string(text, end) + ", which is " + show(double(Real(x))) + " in " + kRealName;
    }
    std::string child_place(std::string_view key) const {
        return place_.empty() ? shown_name(key) : place_ + "." + shown_name(key);
    }

    const Json& value_;
    std::string place_;
    const std::string& file_;
};

constexpr std::string_view kTopKeys[] = {"description", "camera", "image",   "materials",
                                         "shapes",      "lights", "medium", "effects"};
constexpr std::string_view kMediumKeys[] = {"sigma_a", "sigma_s", "g"};
constexpr std::string_view kCameraKeys[] = {"from", "at", "up", "vfov", "aperture", "focus_distance"};
constexpr std::string_view kImageKeys[] = {"width", "height", "spp"};
constexpr std::string_view kShapeTypes[] = {"sphere", "quad", "triangle", "plane", "box", "mesh"};
constexpr std::string_view kLightTypes[] = {"point", "environment"};
constexpr std::string_view kTransformKeys[] = {"scale", "rotate_x", "rotate_y", "rotate_z", "translate"};

CameraDesc read_camera(const Node& node) {
    node.expect_object(kCameraKeys);
    CameraDesc camera;
    camera.from = node["from"].vec3();
    camera.at = node["at"].vec3();
    if (node.has("up")) camera.up = node["up"].direction();
    if (node.has("vfov")) camera.vfov = node["vfov"].real_in(0, 180, true, true);
    if (node.has("aperture")) camera.aperture = node["aperture"].real_in(0, kLargestNumber, false, false);
    if (node.has("focus_distance")) camera.focus_distance = node["focus_distance"].positive();
    if (!normalisable(camera.at - camera.from)) {
        node["at"].fail("must differ from camera.from, so that at - from is a direction, got at - from = " +
                        show(camera.at - camera.from));
    }
    if (parallel(Vec3d(camera.at - camera.from), Vec3d(camera.up))) {
        node["up"].fail("must not be parallel to the view direction at - from = " +
                        show(camera.at - camera.from) + ", got " + show(camera.up));
    }
    return camera;
}

ImageDesc read_image(const Node& node) {
    node.expect_object(kImageKeys);
    ImageDesc image;
    if (node.has("width")) image.width = node["width"].integer(1, kMaxImageSide);
    if (node.has("height")) image.height = node["height"].integer(1, kMaxImageSide);
    if (node.has("spp")) image.spp = node["spp"].integer(1, kMaxSamplesPerPixel);
    // Whether width × height fits in memory is checked for the size that will be rendered, which --width and
    // --height may change (app.cpp).
    return image;
}

// A participating medium (chapter 09): coefficients >= 0 per unit of length, |g| < 1.
MediumDesc read_medium(const Node& node) {
    node.expect_object(kMediumKeys, "a medium");
    MediumDesc medium;
    if (node.has("sigma_a")) medium.sigma_a = node["sigma_a"].color_in(kLargestNumber);
    if (node.has("sigma_s")) medium.sigma_s = node["sigma_s"].color_in(kLargestNumber);
    if (node.has("g")) medium.g = node["g"].real_in(-1, 1, true, true);
    return medium;
}

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

TextureDesc read_checker(const Node& node) {
    node.expect_object(std::array<std::string_view, 1>{"checker"}, "a checker texture");
    const Node checker = node["checker"];
    checker.expect_object(kCheckerKeys, "a checker");
    CheckerDesc desc;
    if (checker.has("even")) desc.even = checker["even"].color_in(1);
    if (checker.has("odd")) desc.odd = checker["odd"].color_in(1);
    if (checker.has("scale")) desc.scale = checker["scale"].positive();
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

Transform read_transform(const Node& node) {
    node.expect_object(kTransformKeys);
    Transform t;
    if (node.has("scale")) {
        const Node scale = node["scale"];
        t.scale = scale.json().is_array() ? scale.vec3() : Vec3(scale.real());
        for (int i = 0; i < 3; ++i) {
            if (t.scale[i] == 0) scale.fail("must not be zero (it would flatten the shape)");
        }
    }
    if (node.has("rotate_x")) t.rotate_degrees.x = node["rotate_x"].real();
    if (node.has("rotate_y")) t.rotate_degrees.y = node["rotate_y"].real();
    if (node.has("rotate_z")) t.rotate_degrees.z = node["rotate_z"].real();
    if (node.has("translate")) t.translate = node["translate"].vec3();
    return t;
}

// |a × b| ≤ 1e-7 |a| |b| (in double), or a × b too short for float to normalise: the parallelogram (or
// triangle) of a and b has no area worth rendering, and its normal would be NaN.
bool zero_area(const Vec3& a, const Vec3& b) {
    const Vec3d da(a), db(b);
    return glm::length(glm::cross(da, db)) <= 1e-7 * glm::length(da) * glm::length(db) ||
           !normalisable(glm::cross(a, b));
}

// A point after a transform (scale · rotation + translation) must stay inside the limits of a scene file.
void check_within_limits(const Node& node, const std::string& what, const Vec3& p) {
    for (int i = 0; i < 3; ++i) {
        if (!(std::abs(double(p[i])) <= kLargestNumber)) {
            node.fail("moves " + what + " to " + show(p) + ", beyond the limit of " + show(kLargestNumber));
        }
    }
}

// The triangles a polygon (a, b, c, ...) is split into: the fan (a, b, c), (a, c, d), ...
template <class Corners>
void add_fan(const std::vector<std::uint32_t>& polygon, Corners& triangles) {
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
        triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
}

// A mesh file's polygons as triangles: an OBJ file (obj_parser.hpp) with its own indices for texture
// coordinates and normals, or a PLY file (ply_parser.hpp) whose vertices carry them. The normals are not yet
// transformed.
void read_obj_into(MeshShape& mesh, std::string_view text) {
    ObjMesh parsed = parse_obj(text, kLargestNumber);
    mesh.positions = std::move(parsed.positions);
    mesh.normals = std::move(parsed.normals);
    mesh.texture_coordinates = std::move(parsed.texture_coordinates);
    for (const ObjFace& face : parsed.faces) {
        add_fan(face.vertices, mesh.triangles);
        if (!face.normals.empty()) add_fan(face.normals, mesh.normal_corners);
        if (!face.texture_coordinates.empty()) add_fan(face.texture_coordinates, mesh.texture_corners);
    }
}

void read_ply_into(MeshShape& mesh, std::string_view bytes) {
    PlyMesh parsed = parse_ply(bytes, kLargestNumber);
    mesh.positions = std::move(parsed.positions);
    mesh.normals = std::move(parsed.normals);
    mesh.texture_coordinates = std::move(parsed.texture_coordinates);
    for (const std::vector<std::uint32_t>& face : parsed.faces) add_fan(face, mesh.triangles);
    if (!mesh.normals.empty()) mesh.normal_corners = mesh.triangles;
    if (!mesh.texture_coordinates.empty()) mesh.texture_corners = mesh.triangles;
}

bool is_ply(const fs::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = char(std::tolower((unsigned char)c));
    return extension == ".ply";
}

// A mesh file's triangles, read strictly: OBJ, or PLY by its extension (.ply, any case). Polygons are split
// into fans (0, k, k + 1). A mesh whose every face has no area after its transform (repeated or collinear
// vertices, or coordinates so small that float's cross product underflows) is refused, as a lone triangle of
// no area is. Normals follow the transform's inverse transpose and are normalised.
MeshShape read_mesh(const Node& node, const fs::path& scene_folder) {
    MeshShape mesh;
    const Node file = node["file"];
    mesh.file = file.string();
    if (node.has("transform")) mesh.transform = read_transform(node["transform"]);
    const fs::path path = scene_folder / mesh.file;
    const std::string shown_file = shown(path);
    const bool ply = is_ply(path);
    if (const std::string problem = not_a_regular_file(path); !problem.empty()) {
        file.fail(std::string("must name an OBJ or PLY file, got ") + shown_file + " (" + problem + ")");
    }
    // The text is read here; an OBJ's "mtllib" line cannot make the loader open another file.
    std::string text;
    try {
        text = read_whole_file(path);
    } catch (const InputError& e) {
        file.fail(shown_file + ": " + e.what());
    }
    try {
        if (ply) {
            read_ply_into(mesh, text);
        } else {
            read_obj_into(mesh, text);
        }
    } catch (const InputError& e) {
        file.fail(shown_file + ": " + e.what());
    }
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        mesh.positions[i] = mesh.transform.apply_to_point(mesh.positions[i]);
        if (node.has("transform")) {
            check_within_limits(node["transform"], "vertex " + std::to_string(i + 1), mesh.positions[i]);
        }
    }
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
        const Vec3 n = mesh.transform.apply_to_normal(mesh.normals[i]);
        if (!normalisable(n)) {
            file.fail(shown_file + ": normal " + std::to_string(i + 1) + " is too short to normalise" +
                      (node.has("transform") ? " after the transform" : ""));
        }
        mesh.normals[i] = glm::normalize(n);
    }
    std::size_t with_area = 0;
    for (const auto& [a, b, c] : mesh.triangles) {
        if (!zero_area(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]))
            ++with_area;
    }
    if (mesh.triangles.empty()) file.fail(shown_file + ": must have at least one face, got none");
    if (with_area == 0) {
        file.fail(shown_file + ": must have at least one face with an area, got " +
                  std::to_string(mesh.triangles.size()) +
                  " triangle(s), each with repeated or collinear vertices" +
                  (node.has("transform") ? " after the transform" : ""));
    }
    return mesh;
}

Shape read_shape(const Node& node, const std::map<std::string, int>& material_index, const fs::path& folder,
                 const std::vector<std::string_view>& material_names) {
    if (!node.json().is_object()) node.fail("must be an object, got " + std::string(node.json().type_name()));
    const std::string type = node["type"].string();
    Shape shape;
    shape.place = node.place();
    using Keys = std::vector<std::string_view>;
    auto keys = [](Keys k) {
        k.push_back("type");
        k.push_back("material");
        return k;
    };
    if (type == "sphere") {
        node.expect_object(keys({"center", "radius"}), "a sphere");
        shape.geometry = SphereShape{node["center"].vec3(), node["radius"].positive()};
    } else if (type == "quad") {
        node.expect_object(keys({"origin", "u", "v"}), "a quad");
        QuadShape q{node["origin"].vec3(), node["u"].vec3(), node["v"].vec3()};
        if (zero_area(q.u, q.v)) {
            node.fail("quad must have an area (u and v not parallel, not zero), got u = " + show(q.u) +
                      ", v = " + show(q.v));
        }
        shape.geometry = q;
    } else if (type == "triangle") {
        node.expect_object(keys({"vertices"}), "a triangle");
        const Node vertices = node["vertices"];
        if (vertices.array_size() != 3)
            vertices.fail("must be an array of 3 vertices, got " + std::to_string(vertices.array_size()));
        TriangleShape t{{vertices.element(0).vec3(), vertices.element(1).vec3(), vertices.element(2).vec3()}};
        if (zero_area(t.vertices[1] - t.vertices[0], t.vertices[2] - t.vertices[0])) {
            node.fail("triangle must have an area (vertices neither repeated nor collinear), got " +
                      show(t.vertices[0]) + ", " + show(t.vertices[1]) + ", " + show(t.vertices[2]));
        }
        shape.geometry = t;
    } else if (type == "plane") {
        node.expect_object(keys({"point", "normal"}), "a plane");
        shape.geometry = PlaneShape{node["point"].vec3(), node["normal"].direction()};
    } else if (type == "box") {
        node.expect_object(keys({"min", "max", "transform"}), "a box");
        BoxShape b{node["min"].vec3(), node["max"].vec3(), {}};
        for (int i = 0; i < 3; ++i) {
            if (!(b.max[i] > b.min[i])) {
                node["max"].fail("must exceed min on every axis, got min " + show(b.min) + ", max " +
                                 show(b.max));
            }
        }
        if (node.has("transform")) {
            b.transform = read_transform(node["transform"]);
            for (int corner = 0; corner < 8; ++corner) {
                const Vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                             (corner & 4) ? b.max.z : b.min.z);
                check_within_limits(node["transform"], "corner " + show(p), b.transform.apply_to_point(p));
            }
        }
        shape.geometry = b;
    } else if (type == "mesh") {
        node.expect_object(keys({"file", "transform"}), "a mesh");
        shape.geometry = read_mesh(node, folder);
    } else {
        node["type"].fail("unknown shape type " + quote(type) + suggestion(type, kShapeTypes) +
                          "; expected sphere, quad, triangle, plane, box or mesh");
    }
    const Node material = node["material"];
    const std::string name = material.string();
    const auto found = material_index.find(name);
    if (found == material_index.end()) {
        material.fail("unknown material " + quote(name) + suggestion(name, material_names));
    }
    shape.material = found->second;
    return shape;
}

// An environment light: a constant `radiance`, or an `image` (environment_image.hpp) with its `scale` and
// `rotate_y`. The image's radiance must stay finite in float once scaled.
EnvironmentLight read_environment(const Node& node, const fs::path& scene_folder) {
    node.expect_object(std::array<std::string_view, 5>{"type", "radiance", "image", "scale", "rotate_y"},
                       "an environment light");
    if (!node.has("image")) {
        if (node.has("scale") || node.has("rotate_y"))
            node[node.has("scale") ? "scale" : "rotate_y"].fail("applies only to an environment image");
        return EnvironmentLight{node["radiance"].color_in(kLargestNumber)};
    }
    if (node.has("radiance")) node["radiance"].fail("an environment light has a radiance or an image, not both");
    EnvironmentLight light;
    const Node file = node["image"];
    light.image_file = file.string();
    if (node.has("scale")) light.scale = node["scale"].real_in(0, kLargestNumber, true, false);
    if (node.has("rotate_y")) light.rotate_y = node["rotate_y"].real_in(-360, 360, false, false);
    const fs::path path = scene_folder / light.image_file;
    auto image = std::make_shared<Image>();
    try {
        *image = read_environment_image(path);
    } catch (const InputError& e) {
        file.fail(e.what());
    }
    // The radiance the chapters before 06 shade it as: the average over the sphere, each row weighted by the
    // solid angle of its band (sin θ at its centre).
    Vec3d sum(0);
    double weights = 0;
    for (int y = 0; y < image->height(); ++y) {
        const double sin_theta = std::sin(kPi * (y + 0.5) / image->height());
        for (int x = 0; x < image->width(); ++x) {
            const Vec3d scaled = Vec3d(image->at(x, y)) * double(light.scale);
            if (!(std::max({scaled.x, scaled.y, scaled.z}) <= double(std::numeric_limits<Real>::max()))) {
                (node.has("scale") ? node["scale"] : file).fail("makes pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                   ") of the image infinite, got " + show(double(light.scale)));
            }
            sum += scaled * sin_theta;
        }
        weights += sin_theta * image->width();
    }
    light.radiance = Color(sum / weights);
    light.image = std::move(image);
    return light;
}

void read_light(const Node& node, Scene& scene, const fs::path& folder) {
    if (!node.json().is_object()) node.fail("must be an object, got " + std::string(node.json().type_name()));
    const std::string type = node["type"].string();
    if (type == "point") {
        node.expect_object(std::array<std::string_view, 3>{"type", "position", "intensity"}, "a point light");
        scene.point_lights.push_back({node["position"].vec3(), node["intensity"].color_in(kLargestNumber)});
    } else if (type == "environment") {
        if (scene.environment) node.fail("a scene has at most one environment light");
        scene.environment = read_environment(node, folder);
    } else {
        node["type"].fail("unknown light type " + quote(type) + suggestion(type, kLightTypes) +
                          "; expected point or environment");
    }
}

EffectSet read_effects(const Node& node) {
    EffectSet effects{Effect::kCameraRays};
    for (std::size_t i = 0; i < node.array_size(); ++i) {
        const Node item = node.element(i);
        const std::string name = item.string();
        const auto effect = effect_from_name(name);
        if (!effect) item.fail("unknown effect " + quote(name) + suggestion(name, kEffectNames));
        effects.insert(*effect);
    }
    return effects;
}

}  // namespace

Scene parse_scene(const std::string& text, const fs::path& file) {
    const std::string name = shown(file);
    Json root;
    try {
        root = parse_json_strictly(text);
    } catch (const InputError& e) {
        throw InputError(name + ": " + e.what());
    }
    const Node top(root, "", name);
    top.expect_object(kTopKeys);
    if (top.has("description")) top["description"].string();

    Scene scene;
    scene.file = name;
    scene.camera = read_camera(top["camera"]);
    if (top.has("image")) scene.image = read_image(top["image"]);

    std::map<std::string, int> material_index;
    std::vector<std::string_view> material_names;
    const fs::path folder = file.parent_path();  // empty for a bare file name: the current folder
    if (top.has("materials")) {
        const Node materials = top["materials"];
        if (!materials.json().is_object()) materials.fail("must be an object of named materials");
        for (const auto& [key, value] : root.at("materials").items()) {
            material_index[key] = int(scene.materials.size());
            scene.materials.push_back(
                read_material(Node(value, "materials." + shown_name(key), name), key, folder));
        }
        for (const Material& m : scene.materials) material_names.push_back(m.name);
    }
    if (top.has("shapes")) {
        const Node shapes = top["shapes"];
        for (std::size_t i = 0; i < shapes.array_size(); ++i) {
            scene.shapes.push_back(read_shape(shapes.element(i), material_index, folder, material_names));
        }
    }
    const std::vector<bool> used = scene.used_materials();
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (!used[i]) {
            Node(root, "materials." + shown_name(scene.materials[i].name), name)
                .fail("defined but used by no shape (use it or remove it)");
        }
    }
    if (top.has("lights")) {
        const Node lights = top["lights"];
        for (std::size_t i = 0; i < lights.array_size(); ++i) read_light(lights.element(i), scene, folder);
    }
    if (top.has("medium")) scene.medium = read_medium(top["medium"]);
    if (top.has("effects")) scene.effects = read_effects(top["effects"]);
    return scene;
}

Scene load_scene(const fs::path& file) {
    if (const std::string problem = not_a_regular_file(file); !problem.empty()) {
        throw InputError(shown(file) + ": must be a scene file (JSON), got " + problem);
    }
    std::string text;
    try {
        text = read_whole_file(file);
    } catch (const InputError& e) {
        throw InputError(shown(file) + ": " + e.what());
    }
    return parse_scene(text, file);
}

}  // namespace rt
