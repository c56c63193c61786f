#include "rt/io/pbrt_reader.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <span>
#include <algorithm>
#include <cctype>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/core/scene.hpp"
#include "rt/io/input_file.hpp"
#include "rt/io/pbrt_objects.hpp"
#include "rt/io/pbrt_parameters.hpp"
#include "rt/io/pbrt_tokens.hpp"

namespace rt {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr int kMostNestedIncludes = 32;

// What AttributeBegin saves and AttributeEnd restores (TransformBegin/End: the transform alone).
struct GraphicsState {
    glm::dmat4 ctm{1.0};  // object (or camera) from world before WorldBegin, world from object after it
    bool reverse_orientation = false;
    std::string material_name = "default";  // a key of the translation's materials, or "default"
    Json material = {{"type", "diffuse"}, {"albedo", {0.5, 0.5, 0.5}}};
    std::optional<Json> emission;  // the AreaLightSource in force: the keys its shapes' material gains
};

struct CameraState {
    glm::dmat4 camera_from_world{1.0};
    double fov = 90;
    double lens_radius = 0;
    double focal_distance = 1e6;
    std::string place;
};

class Reader {
  public:
    explicit Reader(const fs::path& main) : main_(main), folder_(main.parent_path()) {}

    // `text`: the main file's contents, or nothing to read it from the file.
    PbrtTranslation run(const std::optional<std::string_view> text) {
        if (text) {
            std::error_code error;
            read_text(*text, shown(main_), {fs::weakly_canonical(main_, error)});
        } else {
            read_file(main_, shown(main_), {});
        }
        if (!world_) throw InputError(shown(main_) + ": no WorldBegin: a pbrt scene needs a world block");
        if (!stack_.empty()) throw InputError(stack_.back().second + "AttributeBegin not closed by AttributeEnd");
        return {finish(), notes_, included_};
    }

  private:
    using Tokens = std::vector<PbrtToken>;

    void read_file(const fs::path& path, const std::string& place, std::vector<fs::path> chain);
    void read_text(std::string_view text, const std::string& place, const std::vector<fs::path>& chain);
    void directive(const Tokens& tokens, std::size_t& at, const std::string& place,
                   const std::vector<fs::path>& chain);
    void include(const std::string& name, const std::string& where, const std::string& place,
                 const std::vector<fs::path>& chain);
    void transform_directive(const std::string& name, const Tokens& tokens, std::size_t& at, const std::string& where,
                             const std::string& place);
    void camera(PbrtParameters& params, const std::string& where);
    // Camera, Film, Sampler, Integrator, PixelFilter, ColorSpace: true when `name` was one of them.
    bool options_directive(const std::string& name, const std::string& type, PbrtParameters& params,
                           const std::string& where);
    // Material, MakeNamedMaterial, NamedMaterial, Shape, AreaLightSource, LightSource.
    bool world_directive(const std::string& name, const std::string& type, PbrtParameters& params,
                         const std::string& where);
    void shape(const std::string& type, PbrtParameters& params, const std::string& where);
    // Texture "name" "spectrum" "imagemap" ...: defines a texture that materials' colours may name.
    void texture(const Tokens& tokens, std::size_t& at, const std::string& where, const std::string& place);
    Json finish();
    void note_ignored(const std::string& what) {
        if (std::find(notes_.begin(), notes_.end(), what) == notes_.end()) notes_.push_back(what);
    }

    fs::path main_, folder_;
    GraphicsState state_;
    std::vector<std::pair<GraphicsState, std::string>> stack_;  // with the place of its AttributeBegin
    std::vector<std::pair<glm::dmat4, std::string>> transform_stack_;
    std::map<std::string, glm::dmat4> coordinate_systems_;
    std::map<std::string, std::pair<Json, std::string>> named_materials_;  // name → material, its place
    pbrt::Textures textures_;
    std::optional<CameraState> camera_;
    bool world_ = false;
    int width_ = 1280, height_ = 720, spp_ = 16;
    int max_depth_ = 5;  // the Integrator's maxdepth: pbrt's default, with or without an Integrator
    std::map<std::string, Json> materials_;  // the translation's materials, as used by shapes
    Json shapes_ = Json::array(), lights_ = Json::array();
    std::optional<Json> environment_;
    std::vector<std::string> notes_;
    std::vector<fs::path> included_;
    int anonymous_materials_ = 0;
};

std::string word_of(const PbrtToken& t) {
    return t.kind == PbrtTokenKind::kString ? "\"" + t.text + "\"" : t.text;
}

// The next token, which must be a quoted string (a directive's type or name).
std::string next_string(const std::vector<PbrtToken>& tokens, std::size_t& at, const std::string& place,
                        const std::string& directive) {
    if (at >= tokens.size() || tokens[at].kind != PbrtTokenKind::kString) {
        const PbrtToken& t = at < tokens.size() ? tokens[at] : tokens[at - 1];
        throw InputError(pbrt_location(place, t) + directive + ": expected a quoted name, got " +
                         (at < tokens.size() ? word_of(t) : "the end of the file"));
    }
    return tokens[at++].text;
}

// The next `count` numbers, bracketed or not.
std::vector<double> next_numbers(const std::vector<PbrtToken>& tokens, std::size_t& at, const std::string& place,
                                 const std::string& directive, std::size_t count) {
    const bool bracket = at < tokens.size() && tokens[at].kind == PbrtTokenKind::kOpen;
    if (bracket) ++at;
    std::vector<double> numbers;
    while (numbers.size() < count) {
        if (at >= tokens.size() || tokens[at].kind != PbrtTokenKind::kNumber) {
            const PbrtToken& t = at < tokens.size() ? tokens[at] : tokens.back();
            throw InputError(pbrt_location(place, t) + directive + ": expected " + std::to_string(count) +
                             " numbers, got " + (at < tokens.size() ? word_of(t) : "the end of the file") +
                             " after " + std::to_string(numbers.size()));
        }
        numbers.push_back(tokens[at++].number);
    }
    if (bracket) {
        if (at >= tokens.size() || tokens[at].kind != PbrtTokenKind::kClose) {
            const PbrtToken& t = at < tokens.size() ? tokens[at] : tokens.back();
            throw InputError(pbrt_location(place, t) + directive + ": expected ] after " + std::to_string(count) +
                             " numbers");
        }
        ++at;
    }
    return numbers;
}

// pbrt's LookAt: camera from world, with the camera's x axis up × view (left-handed, as pbrt's is).
glm::dmat4 look_at(const Vec3d& eye, const Vec3d& look, const Vec3d& up, const std::string& where) {
    const Vec3d dir = look - eye;
    if (!(glm::length(dir) > 0)) throw InputError(where + "LookAt: the eye and the point looked at coincide");
    const Vec3d d = glm::normalize(dir);
    const Vec3d cross = glm::cross(glm::length(up) > 0 ? glm::normalize(up) : up, d);
    if (!(glm::length(cross) > 1e-12)) throw InputError(where + "LookAt: up is parallel to the view direction");
    const Vec3d right = glm::normalize(cross), new_up = glm::cross(d, right);
    glm::dmat4 world_from_camera(1.0);
    world_from_camera[0] = glm::dvec4(right, 0);
    world_from_camera[1] = glm::dvec4(new_up, 0);
    world_from_camera[2] = glm::dvec4(d, 0);
    world_from_camera[3] = glm::dvec4(eye, 1);
    return glm::inverse(world_from_camera);
}

void Reader::read_file(const fs::path& path, const std::string& place, std::vector<fs::path> chain) {
    std::string text;
    try {
        text = read_whole_file(path);
    } catch (const InputError& e) {
        throw InputError(place + ": " + e.what());
    }
    std::error_code error;
    chain.push_back(fs::weakly_canonical(path, error));
    read_text(text, place, chain);
}

void Reader::read_text(std::string_view text, const std::string& place, const std::vector<fs::path>& chain) {
    const Tokens tokens = tokenize_pbrt(text, place);
    std::size_t at = 0;
    while (at < tokens.size()) directive(tokens, at, place, chain);
}

void Reader::include(const std::string& name, const std::string& where, const std::string& place,
                     const std::vector<fs::path>& chain) {
    const fs::path path = folder_ / name;
    if (const std::string problem = not_a_regular_file(path); !problem.empty()) {
        throw InputError(where + "Include \"" + printable(name, 64) + "\": cannot be read (" + problem + ")");
    }
    std::error_code error;
    const fs::path canonical = fs::weakly_canonical(path, error);
    for (const fs::path& p : chain) {
        if (p == canonical) throw InputError(where + "Include \"" + printable(name, 64) + "\": that file is already being read (an Include cycle)");
    }
    if (chain.size() >= kMostNestedIncludes) {
        throw InputError(where + "Include: more than " + std::to_string(kMostNestedIncludes) + " files nested");
    }
    (void)place;
    included_.push_back(path);
    read_file(path, shown(main_) + ": " + shown(path), chain);
}

// The directives the course knows but does not implement, with what it would take.
constexpr std::string_view kRefusedDirectives[] = {"ObjectBegin",     "ObjectEnd",       "ObjectInstance",
                                                   "MakeNamedMedium", "MediumInterface", "TransformTimes",
                                                   "ActiveTransform", "Attribute",       "Option"};
constexpr std::string_view kTransformDirectives[] = {"Identity", "Translate", "Scale", "Rotate", "LookAt", "Transform",
                                                     "ConcatTransform", "CoordinateSystem", "CoordSysTransform"};
// Directives followed by a quoted type or name and a parameter list.
constexpr std::string_view kTypedDirectives[] = {"Camera", "Film", "Sampler", "Integrator", "PixelFilter",
                                                 "ColorSpace", "Material", "MakeNamedMaterial", "NamedMaterial",
                                                 "Shape", "AreaLightSource", "LightSource"};

bool listed(std::string_view name, std::span<const std::string_view> list) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

void Reader::directive(const Tokens& tokens, std::size_t& at, const std::string& place,
                       const std::vector<fs::path>& chain) {
    const PbrtToken& token = tokens[at++];
    const std::string where = pbrt_location(place, token);
    if (token.kind != PbrtTokenKind::kWord || token.text.empty() || !std::isupper(static_cast<unsigned char>(token.text[0]))) {
        throw InputError(where + "expected a directive (Shape, Material, ...), got " + printable(word_of(token), 64));
    }
    const std::string& name = token.text;
    if (listed(name, kTransformDirectives)) {
        transform_directive(name, tokens, at, where, place);
    } else if (name == "ReverseOrientation") {
        state_.reverse_orientation = !state_.reverse_orientation;
    } else if (name == "WorldBegin") {
        if (world_) throw InputError(where + "WorldBegin given twice");
        world_ = true;
        state_.ctm = glm::dmat4(1.0);
        coordinate_systems_["world"] = state_.ctm;
    } else if (name == "AttributeBegin") {
        stack_.emplace_back(state_, where);
    } else if (name == "AttributeEnd") {
        if (stack_.empty()) throw InputError(where + "AttributeEnd without AttributeBegin");
        state_ = stack_.back().first;
        stack_.pop_back();
    } else if (name == "TransformBegin") {
        transform_stack_.emplace_back(state_.ctm, where);
    } else if (name == "TransformEnd") {
        if (transform_stack_.empty()) throw InputError(where + "TransformEnd without TransformBegin");
        state_.ctm = transform_stack_.back().first;
        transform_stack_.pop_back();
    } else if (name == "Include" || name == "Import") {
        include(next_string(tokens, at, place, name), where, place, chain);
    } else if (listed(name, kTypedDirectives)) {
        const std::string type = next_string(tokens, at, place, name);
        const std::string owner = name + " \"" + printable(type, 64) + "\"";
        PbrtParameters params(read_pbrt_parameters(tokens, at, place), place, where, owner);
        if (!options_directive(name, type, params, where)) world_directive(name, type, params, where);
    } else if (name == "Texture") {
        texture(tokens, at, where, place);
    } else if (listed(name, kRefusedDirectives)) {
        throw InputError(where + name +
                         " is not in the course (it reads the directives listed in assets/scenes/README.md, "
                         "\"pbrt-v4 scenes\")");
    } else {
        throw InputError(where + "unknown directive " + printable(name, 64) +
                         " (the course reads the directives listed in assets/scenes/README.md, \"pbrt-v4 scenes\")");
    }
}

bool Reader::options_directive(const std::string& name, const std::string& type, PbrtParameters& params,
                               const std::string& where) {
    const std::string owner = name + " \"" + printable(type, 64) + "\"";
    if (name == "Camera" || name == "Film" || name == "Sampler" || name == "Integrator" || name == "PixelFilter") {
        if (world_) throw InputError(where + name + " after WorldBegin: it belongs before it");
    }
    if (name == "Camera") {
        if (type != "perspective") throw InputError(where + "camera \"" + type + "\" is not in the course; it reads perspective");
        camera(params, where);
    } else if (name == "Film") {
        if (type != "rgb" && type != "gbuffer") throw InputError(where + "film \"" + type + "\" is not in the course; it reads rgb");
        width_ = params.integer("xresolution").value_or(1280);
        height_ = params.integer("yresolution").value_or(720);
        if (width_ < 1 || width_ > 65536) params.fail("xresolution", "must be in [1, 65536]");
        if (height_ < 1 || height_ > 65536) params.fail("yresolution", "must be in [1, 65536]");
        if (params.ignore("filename")) note_ignored("Film \"filename\" (the course writes what --out names)");
        params.refuse_unused("xresolution, yresolution, filename");
    } else if (name == "Sampler") {
        spp_ = params.integer("pixelsamples").value_or(16);
        if (spp_ < 1 || spp_ > 1048576) params.fail("pixelsamples", "must be in [1, 1048576]");
        for (const char* p : {"seed", "randomization", "dimensions", "jitter", "xsamples", "ysamples"}) {
            if (params.ignore(p)) note_ignored(owner + " \"" + p + "\"");
        }
        params.refuse_unused("pixelsamples");
        note_ignored(owner + " (the course's own sampler)");
    } else if (name == "Integrator") {
        if (type != "path" && type != "volpath") throw InputError(where + "integrator \"" + type + "\" is not in the course; it reads path and volpath");
        // pbrt's path of maxdepth N and the course's depth cap N count the same paths (chapter 06's loop
        // traces the ray drawn at the cap for the light it meets).
        max_depth_ = params.integer("maxdepth").value_or(max_depth_);
        if (max_depth_ < 1 || max_depth_ > kMaxPathDepth)
            params.fail("maxdepth", "must be in [1, " + std::to_string(kMaxPathDepth) +
                                        "] (the bounces a course path may make), got " +
                                        std::to_string(max_depth_));
        if (params.ignore("lightsampler")) note_ignored(owner + " \"lightsampler\" (the course picks lights by power)");
        params.refuse_unused("maxdepth, lightsampler");
    } else if (name == "PixelFilter") {
        for (const char* p : {"xradius", "yradius", "sigma", "B", "C", "tau"}) params.ignore(p);
        params.refuse_unused("xradius, yradius, sigma, B, C, tau");
        note_ignored(owner + " and its parameters (the course averages each pixel's samples, a box filter)");
    } else if (name == "ColorSpace") {
        if (type != "srgb") throw InputError(where + "ColorSpace \"" + type + "\" is not in the course; it renders in srgb");
        params.refuse_unused("nothing");
    } else {
        return false;
    }
    return true;
}

bool Reader::world_directive(const std::string& name, const std::string& type, PbrtParameters& params,
                             const std::string& where) {
    if (!world_) throw InputError(where + name + " before WorldBegin: it belongs in the world block");
    const std::string type_place = where;
    std::vector<std::string> notes;
    if (name == "Material") {
        state_.material = pbrt::material(type, params, type_place, textures_, notes);
        state_.material_name = "Material " + type + " " + std::to_string(++anonymous_materials_);
    } else if (name == "MakeNamedMaterial") {
        const std::optional<std::string> material_type = params.string("type");
        if (!material_type) params.fail("type", "MakeNamedMaterial needs \"string type\"");
        if (named_materials_.count(type)) throw InputError(where + "MakeNamedMaterial \"" + printable(type, 64) + "\": defined twice");
        named_materials_[type] = {pbrt::material(*material_type, params, type_place, textures_, notes),
                                  where};
    } else if (name == "NamedMaterial") {
        params.refuse_unused("nothing");
        const auto found = named_materials_.find(type);
        if (found == named_materials_.end()) throw InputError(where + "NamedMaterial: unknown material \"" + printable(type, 64) + "\"");
        state_.material = found->second.first;
        state_.material_name = type;
    } else if (name == "Shape") {
        shape(type, params, where);
    } else if (name == "AreaLightSource") {
        if (type != "diffuse") throw InputError(where + "area light \"" + type + "\" is not in the course; it reads diffuse");
        state_.emission = pbrt::area_emission(params);
    } else if (name == "LightSource") {
        Json light = pbrt::light(type, params, state_.ctm, where);
        if (light["type"] == "environment") {
            if (environment_) throw InputError(where + "a second infinite light: the course has one environment");
            environment_ = std::move(light);
        } else {
            lights_.push_back(std::move(light));
        }
    } else {
        return false;
    }
    for (const std::string& note : notes) note_ignored(note);
    return true;
}

void Reader::transform_directive(const std::string& name, const Tokens& tokens, std::size_t& at,
                                 const std::string& where, const std::string& place) {
    glm::dmat4& ctm = state_.ctm;
    if (name == "Identity") {
        ctm = glm::dmat4(1.0);
    } else if (name == "Translate") {
        const auto v = next_numbers(tokens, at, place, name, 3);
        ctm = glm::translate(ctm, Vec3d(v[0], v[1], v[2]));
    } else if (name == "Scale") {
        const auto v = next_numbers(tokens, at, place, name, 3);
        ctm = glm::scale(ctm, Vec3d(v[0], v[1], v[2]));
    } else if (name == "Rotate") {
        const auto v = next_numbers(tokens, at, place, name, 4);
        const Vec3d axis(v[1], v[2], v[3]);
        if (!(glm::length(axis) > 0)) throw InputError(where + "Rotate: the axis must not be zero");
        ctm = glm::rotate(ctm, v[0] * std::numbers::pi / 180, glm::normalize(axis));
    } else if (name == "LookAt") {
        const auto v = next_numbers(tokens, at, place, name, 9);
        ctm = ctm * look_at({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}, where);
    } else if (name == "Transform" || name == "ConcatTransform") {
        const auto v = next_numbers(tokens, at, place, name, 16);
        glm::dmat4 m;  // pbrt lists the matrix column by column, as glm stores it
        for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = v[std::size_t(i)];
        if (!(std::abs(glm::determinant(m)) > 1e-30)) throw InputError(where + name + ": the matrix is not invertible");
        ctm = name == "Transform" ? m : ctm * m;
    } else if (name == "CoordinateSystem") {
        coordinate_systems_[next_string(tokens, at, place, name)] = ctm;
    } else {  // CoordSysTransform
        const std::string system = next_string(tokens, at, place, name);
        const auto found = coordinate_systems_.find(system);
        if (found == coordinate_systems_.end()) {
            throw InputError(where + "CoordSysTransform: unknown coordinate system \"" + printable(system, 64) + "\"");
        }
        ctm = found->second;
    }
}

void Reader::texture(const Tokens& tokens, std::size_t& at, const std::string& where,
                     const std::string& place) {
    const std::string name = next_string(tokens, at, place, "Texture");
    const std::string type = next_string(tokens, at, place, "Texture");
    const std::string kind = next_string(tokens, at, place, "Texture");
    PbrtParameters params(read_pbrt_parameters(tokens, at, place), place, where,
                          "Texture \"" + printable(name, 64) + "\"");
    if (!world_) throw InputError(where + "Texture before WorldBegin: it belongs in the world block");
    if (textures_.count(name))
        throw InputError(where + "Texture \"" + printable(name, 64) + "\": defined twice");
    std::vector<std::string> notes;
    Json course = pbrt::texture(kind, type, params, where, notes);
    // An image from the main scene's folder, as an Include: a file that cannot be read is refused here, at
    // its place.
    if (course.contains("texture")) {
        const std::string file = course["texture"].get<std::string>();
        if (const std::string problem = not_a_regular_file(folder_ / file); !problem.empty()) {
            params.fail("filename", "\"" + printable(file, 64) + "\" cannot be read (" + problem + ")");
        }
    }
    textures_[name] = {type, std::move(course)};
    for (const std::string& note : notes) note_ignored(note);
}

void Reader::camera(PbrtParameters& params, const std::string& where) {
    CameraState c;
    c.camera_from_world = state_.ctm;
    c.place = where;
    c.fov = params.real("fov").value_or(90);
    if (!(c.fov > 0 && c.fov < 180)) params.fail("fov", "must be in (0, 180), got " + show_pbrt_number(c.fov));
    c.lens_radius = params.real("lensradius").value_or(0);
    if (!(c.lens_radius >= 0 && c.lens_radius <= 1e9)) params.fail("lensradius", "must be in [0, 1e9]");
    c.focal_distance = params.real("focaldistance").value_or(1e6);
    if (!(c.focal_distance > 0 && c.focal_distance <= 1e9)) params.fail("focaldistance", "must be in (0, 1e9]");
    params.refuse_unused("fov, lensradius, focaldistance");
    camera_ = c;
    coordinate_systems_["camera"] = glm::inverse(state_.ctm);
}

void Reader::shape(const std::string& type, PbrtParameters& params, const std::string& where) {
    if (!world_) throw InputError(where + "Shape before WorldBegin");
    Json s = pbrt::shape(type, params, state_.ctm, state_.reverse_orientation, state_.emission.has_value(), where);
    Json m = state_.material;
    std::string name = state_.material_name;
    if (state_.emission) {
        if (m["type"] == "dielectric") {
            throw InputError(where + "Shape under AreaLightSource with a dielectric material: the course's glass "
                             "does not emit");
        }
        if (type == "sphere" && state_.emission->contains("two_sided")) {
            throw InputError(where +
                             "Shape \"sphere\" under a twosided AreaLightSource: the course's sphere "
                             "lights emit outward only (two-sided: trianglemesh, plymesh)");
        }
        m.update(*state_.emission);
        name += " (emitting)";
    }
    // One course material per distinct content under one name: "Light (emitting)", "Light (emitting) 2", ...
    std::string key = name;
    for (int n = 2; materials_.count(key) && materials_[key] != m; ++n) key = name + " " + std::to_string(n);
    materials_[key] = m;
    s["material"] = key;
    shapes_.push_back(std::move(s));
}

Json Reader::finish() {
    const CameraState c = camera_.value_or(CameraState{});
    const glm::dmat4 world_from_camera = glm::inverse(c.camera_from_world);
    const glm::dmat3 axes(world_from_camera);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (std::abs(glm::dot(axes[i], axes[j]) - (i == j ? 1.0 : 0.0)) > 1e-4) {
                throw InputError((c.place.empty() ? shown(main_) + ": " : c.place) +
                                 "Camera: its transform must be a rotation and translation (with a mirror at "
                                 "most): the course's camera has no scale or shear");
            }
        }
    }
    const Vec3d eye(world_from_camera[3]), right = axes[0], up = axes[1], forward = axes[2];
    // pbrt's fov spans the shorter side of the image; the course's vfov the height.
    const double half = std::tan(c.fov * std::numbers::pi / 360);
    const double vfov = width_ < height_ ? 360 / std::numbers::pi * std::atan(half * height_ / width_) : c.fov;
    Json camera = {{"from", {eye.x, eye.y, eye.z}},
                   {"at", {eye.x + forward.x, eye.y + forward.y, eye.z + forward.z}},
                   {"up", {up.x, up.y, up.z}},
                   {"vfov", vfov}};
    if (glm::dot(right, glm::cross(forward, up)) < 0) camera["mirrored"] = true;
    if (c.lens_radius > 0) {
        camera["aperture"] = c.lens_radius;
        camera["focus_distance"] = c.focal_distance;
    }
    Json scene = {{"camera", camera}, {"image", {{"width", width_}, {"height", height_}, {"spp", spp_}}}};
    scene["max_depth"] = max_depth_;
    if (!materials_.empty()) scene["materials"] = materials_;
    if (!shapes_.empty()) scene["shapes"] = shapes_;
    if (environment_) lights_.push_back(*environment_);
    if (!lights_.empty()) scene["lights"] = lights_;
    return scene;
}

}  // namespace

bool is_pbrt_file(const fs::path& file) {
    std::string extension = file.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".pbrt";
}

PbrtTranslation translate_pbrt(const fs::path& file) {
    return Reader(file).run(std::nullopt);
}

PbrtTranslation translate_pbrt_text(std::string_view text, const fs::path& file) {
    return Reader(file).run(text);
}

}  // namespace rt
