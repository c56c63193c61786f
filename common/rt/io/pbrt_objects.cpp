#include "rt/io/pbrt_objects.hpp"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/pbrt_spectra.hpp"
#include "rt/io/scene_loader.hpp"

namespace rt::pbrt {
namespace {

Json to_json(const Vec3d& v) {
    return Json::array({v.x, v.y, v.z});
}

// A colour parameter checked to lie in [low, high] per channel.
Vec3d color_in(PbrtParameters& params, std::string_view name, Vec3d fallback, double high) {
    const Vec3d c = params.color(name).value_or(fallback);
    for (int i = 0; i < 3; ++i) {
        if (!(c[i] >= 0 && c[i] <= high)) {
            params.fail(name, std::string("each channel must be in [0, ") + (high == 1 ? "1" : "1e9") + "], got " +
                                  show_pbrt_number(c[i]));
        }
    }
    return c;
}

// A colour parameter given as a value in [0, high] per channel, or as a spectrum texture (a checkerboard's
// colours in the same range): the course's [r, g, b] or texture object.
Json colour_or_texture(PbrtParameters& params, std::string_view name, Vec3d fallback, double high,
                       const Textures& textures) {
    const std::optional<std::string> named = params.texture(name);
    if (!named) return to_json(color_in(params, name, fallback, high));
    const auto found = textures.find(*named);
    const std::string quoted = "texture \"" + printable(*named, 64) + "\"";
    if (found == textures.end()) params.fail(name, "unknown " + quoted + " (a Texture directive defines it)");
    if (found->second.type != "spectrum")
        params.fail(name, quoted + " is a float texture; a colour takes a spectrum one");
    const Json& course = found->second.course;
    if (course.contains("checker")) {
        for (const char* square : {"even", "odd"}) {
            for (const Json& c : course["checker"][square]) {
                if (!(c.get<double>() <= high)) {
                    params.fail(name,
                                quoted + ": its values must be in [0, " + show_pbrt_number(high) + "] here");
                }
            }
        }
    }
    return course;
}

// The course's roughness r (GGX α = r²) for pbrt's "roughness" (or equal "uroughness" and "vroughness"):
// α = roughness, or √roughness with "remaproughness" true (pbrt's default). pbrt treats α below 10⁻³ as
// smooth, and so does the course (roughness 0).
double roughness(PbrtParameters& params) {
    const bool remap = params.boolean("remaproughness").value_or(true);
    double value = params.real("roughness").value_or(0);
    const std::optional<double> u = params.real("uroughness"), v = params.real("vroughness");
    if (u || v) {
        if (params.has("roughness")) params.fail("uroughness", "give roughness or uroughness/vroughness, not both");
        if (u.value_or(0) != v.value_or(0)) {
            params.fail("uroughness", "must equal vroughness: the course's microfacets are isotropic");
        }
        value = u.value_or(0);
    }
    if (!(value >= 0)) params.fail(u ? "uroughness" : "roughness", "must be >= 0, got " + show_pbrt_number(value));
    const double alpha = remap ? std::sqrt(value) : value;
    if (alpha > 1) params.fail(u ? "uroughness" : "roughness", "gives alpha " + show_pbrt_number(alpha) + " above 1, beyond the course's range");
    return alpha < 1e-3 ? 0.0 : std::sqrt(alpha);
}

Json conductor(PbrtParameters& params, const Textures& textures) {
    Json eta, k;
    if (params.has("reflectance")) {
        if (params.has("eta") || params.has("k")) params.fail("reflectance", "give eta and k or reflectance, not both");
        // pbrt-v4: η = 1 and k = 2 √r / √(1 − r), the metal whose reflectance at normal incidence is r.
        const Vec3d r = color_in(params, "reflectance", Vec3d(0), 1);
        Vec3d from_r;
        for (int i = 0; i < 3; ++i) {
            if (r[i] >= 1) params.fail("reflectance", "must be below 1 in every channel (k would be infinite)");
            from_r[i] = 2 * std::sqrt(r[i]) / std::sqrt(1 - r[i]);
        }
        eta = to_json(Vec3d(1));
        k = to_json(from_r);
    } else {
        eta = colour_or_texture(params, "eta", *pbrt_named_spectrum("metal-Cu-eta"), kLargestSceneNumber,
                                textures);
        k = colour_or_texture(params, "k", *pbrt_named_spectrum("metal-Cu-k"), kLargestSceneNumber, textures);
    }
    Json m = {{"type", "conductor"}, {"eta", std::move(eta)}, {"k", std::move(k)}};
    if (const double r = roughness(params); r > 0) m["roughness"] = r;
    return m;
}

Json dielectric(PbrtParameters& params) {
    const double eta = params.real("eta").value_or(1.5);
    if (!(eta >= 1 && eta <= 10)) {
        params.fail("eta", "must be in [1, 10] (the course's dielectrics are at least as dense as the space around them), got " +
                               show_pbrt_number(eta));
    }
    Json m = {{"type", "dielectric"}, {"ior", eta}};
    if (const double r = roughness(params); r > 0) m["roughness"] = r;
    return m;
}

// pbrt-v4's coated diffuse, as the course's smooth clear coat over a Lambert base (chapter 07,
// coated_diffuse.hpp): "reflectance" and "eta" are its base and coat. pbrt's layer between them is a
// medium of thickness "thickness" (0.01 unless given) and of single-scattering "albedo" (0: it only
// absorbs, exp(−thickness / cos θ) at each crossing), walked "nsamples" times for at most "maxdepth" bounces.
// The course's coat has no layer: a scattering one (albedo > 0) and a rough coat are refused; thickness,
// maxdepth and nsamples are named in the notes.
Json coated_diffuse(PbrtParameters& params, const Textures& textures, std::vector<std::string>& notes) {
    const double eta = params.real("eta").value_or(1.5);
    if (!(eta >= 1 && eta <= 10)) {
        params.fail(
            "eta",
            "must be in [1, 10] (the course's coat is at least as dense as the space around it), got " +
                show_pbrt_number(eta));
    }
    if (roughness(params) > 0)
        params.fail(params.has("roughness") ? "roughness" : "uroughness",
                    "a rough coat is not in the course: its coateddiffuse has a smooth coat (roughness 0, "
                    "pbrt's default)");
    const Vec3d albedo = color_in(params, "albedo", Vec3d(0), 1);
    if (albedo != Vec3d(0))
        params.fail("albedo", "a scattering layer under the coat is not in the course (albedo 0 only)");
    params.ignore("g");  // the layer's phase function: nothing scatters with albedo 0
    const double thickness = params.real("thickness").value_or(0.01);
    if (!(thickness > 0 && thickness <= kLargestSceneNumber))
        params.fail("thickness", "must be > 0, got " + show_pbrt_number(thickness));
    notes.push_back(
        "Material \"coateddiffuse\" \"thickness\" " + show_pbrt_number(thickness) +
        " (the course's coat is clear: pbrt's layer absorbs exp(-thickness / cos) at each crossing)");
    for (const char* p : {"maxdepth", "nsamples"}) {
        if (params.ignore(p))
            notes.push_back(std::string("Material \"coateddiffuse\" \"") + p +
                            "\" (the course's coat is exact: no random walk)");
    }
    return {{"type", "coateddiffuse"},
            {"albedo", colour_or_texture(params, "reflectance", Vec3d(0.5), 1, textures)},
            {"ior", eta}};
}

// pbrt-v4's imagemap: an 8-bit PNG or JPEG file (the course's textures), sRGB-encoded unless "encoding" says
// "linear"; repeated uscale × vscale times.
Json image_texture(PbrtParameters& params, std::vector<std::string>& notes) {
    const std::optional<std::string> file = params.string("filename");
    if (!file) params.fail("filename", "an imagemap needs \"string filename\"");
    std::string extension = std::filesystem::path(*file).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".png" && extension != ".jpg" && extension != ".jpeg") {
        params.fail("filename",
                    "the course's textures are 8-bit PNG or JPEG images (float EXR, PFM and HDR "
                    "images and TGA are not in the course), got \"" +
                        printable(*file, 64) + "\"");
    }
    const std::string encoding = params.string("encoding").value_or("sRGB");
    if (encoding != "sRGB" && encoding != "linear")
        params.fail("encoding", "must be sRGB or linear (the course has no gamma encodings)");
    if (params.real("scale").value_or(1) != 1)
        params.fail("scale", "must be 1: the course's textures are not scaled");
    if (params.boolean("invert").value_or(false))
        params.fail("invert", "must be false: the course's textures are not inverted");
    const std::string filter = params.string("filter").value_or("bilinear");
    if (filter == "trilinear" || filter == "ewa" || filter == "EWA") {
        notes.push_back("Texture \"imagemap\" \"filter\" \"" + filter +
                        "\" (the course filters bilinearly, without mip-maps)");
    } else if (filter != "bilinear" && filter != "point") {
        params.fail("filter", "must be point, bilinear, trilinear or ewa");
    }
    if (params.ignore("maxanisotropy"))
        notes.push_back("Texture \"imagemap\" \"maxanisotropy\" (the course filters bilinearly)");
    const std::string wrap = params.string("wrap").value_or("repeat");
    if (wrap != "repeat" && wrap != "clamp")
        params.fail("wrap", "must be repeat or clamp (the course has no black or octahedralsphere wrap)");
    return {{"texture", *file},
            {"encoding", encoding == "sRGB" ? "srgb" : "linear"},
            {"filter", filter == "point" ? "nearest" : "bilinear"},
            {"wrap", wrap}};
}

// pbrt-v4's checkerboard: tex1 where ⌊su u⌋ + ⌊sv v⌋ is even, tex2 elsewhere, each a value (a float one is
// grey); the course's checker has one scale, so uscale and vscale must agree.
Json checkerboard(PbrtParameters& params, const std::string& type) {
    if (params.integer("dimension").value_or(2) != 2)
        params.fail("dimension", "must be 2 (the course has no solid checkerboard)");
    auto value = [&](const char* name, double fallback) {
        if (params.texture(name))
            params.fail(name, "a checkerboard of textures is not in the course: give a value");
        if (type == "float") {
            const double v = params.real(name).value_or(fallback);
            if (!(v >= 0 && v <= kLargestSceneNumber))
                params.fail(name, "must be in [0, 1e9], got " + show_pbrt_number(v));
            return to_json(Vec3d(v));
        }
        return to_json(color_in(params, name, Vec3d(fallback), kLargestSceneNumber));
    };
    return {{"checker", {{"even", value("tex1", 1)}, {"odd", value("tex2", 0)}}}};
}

}  // namespace

Json texture(const std::string& kind, const std::string& type, PbrtParameters& params,
             const std::string& type_place, std::vector<std::string>& notes) {
    if (type != "spectrum" && type != "float") {
        throw InputError(type_place + "texture type \"" + printable(type, 64) +
                         "\" is not pbrt-v4's: spectrum or float");
    }
    if (params.string("mapping").value_or("uv") != "uv")
        params.fail("mapping", "must be uv (the course maps textures by the shapes' uv)");
    const double su = params.real("uscale").value_or(1), sv = params.real("vscale").value_or(1);
    if (!(su > 0 && su <= kLargestSceneNumber))
        params.fail("uscale", "must be in (0, 1e9], got " + show_pbrt_number(su));
    if (!(sv > 0 && sv <= kLargestSceneNumber))
        params.fail("vscale", "must be in (0, 1e9], got " + show_pbrt_number(sv));
    if (params.real("udelta").value_or(0) != 0)
        params.fail("udelta", "must be 0: the course's textures are not offset");
    if (params.real("vdelta").value_or(0) != 0)
        params.fail("vdelta", "must be 0: the course's textures are not offset");
    Json t;
    if (kind == "imagemap") {
        t = image_texture(params, notes);
        t["scale"] = {su, sv};
        params.refuse_unused(
            "filename, encoding, scale 1, invert false, filter, maxanisotropy, wrap, mapping uv, "
            "uscale, vscale, udelta 0, vdelta 0");
    } else if (kind == "checkerboard") {
        if (su != sv) {
            params.fail(params.has("vscale") ? "vscale" : "uscale",
                        "uscale and vscale must be equal: the course's checker has one scale");
        }
        t = checkerboard(params, type);
        t["checker"]["scale"] = su;
        params.refuse_unused("tex1, tex2, dimension 2, mapping uv, uscale, vscale, udelta 0, vdelta 0");
    } else {
        throw InputError(type_place + "texture \"" + printable(kind, 64) +
                         "\" is not in the course; it reads imagemap, checkerboard");
    }
    return t;
}

namespace {

// The course's material, before refuse_unused.
Json course_material(const std::string& type, PbrtParameters& params, const std::string& type_place,
                     const Textures& textures, std::vector<std::string>& notes) {
    if (type == "diffuse")
        return {{"type", "diffuse"},
                {"albedo", colour_or_texture(params, "reflectance", Vec3d(0.5), 1, textures)}};
    if (type == "conductor") return conductor(params, textures);
    if (type == "dielectric") return dielectric(params);
    if (type == "coateddiffuse") return coated_diffuse(params, textures, notes);
    throw InputError(type_place + "material \"" + type +
                     "\" is not in the course; it reads diffuse, conductor, dielectric, coateddiffuse");
}

}  // namespace

Json material(const std::string& type, PbrtParameters& params, const std::string& type_place,
              const Textures& textures, std::vector<std::string>& notes) {
    Json m = course_material(type, params, type_place, textures, notes);
    params.refuse_unused(
        type == "diffuse"     ? "reflectance"
        : type == "conductor" ? "eta, k, reflectance, roughness, uroughness, vroughness, remaproughness"
        : type == "coateddiffuse"
            ? "reflectance, eta, roughness 0, thickness, albedo 0, g, maxdepth, nsamples, remaproughness"
            : "eta, roughness, uroughness, vroughness, remaproughness");
    return m;
}

Json area_emission(PbrtParameters& params) {
    const Vec3d L = color_in(params, "L", Vec3d(1), kLargestSceneNumber);
    const double scale = params.real("scale").value_or(1);
    if (!(scale >= 0)) params.fail("scale", "must be >= 0, got " + show_pbrt_number(scale));
    const bool two_sided = params.boolean("twosided").value_or(false);
    params.refuse_unused("L, scale, twosided");
    const Vec3d emission = L * scale;
    if (std::max({emission.x, emission.y, emission.z}) > kLargestSceneNumber) {
        params.fail("scale", "makes L × scale exceed the course's limit of 1e9");
    }
    Json keys = {{"emission", to_json(emission)}};
    if (two_sided) keys["two_sided"] = true;
    return keys;
}

namespace {

Vec3d point_of(const glm::dmat4& m, const Vec3d& p) {
    return Vec3d(m * glm::dvec4(p, 1.0));
}

Vec3d checked_point(PbrtParameters& params, std::string_view name, const Vec3d& p) {
    for (int i = 0; i < 3; ++i) {
        if (!(std::abs(p[i]) <= kLargestSceneNumber)) {
            params.fail(name, "a point lands beyond the course's limit of 1e9 after the transform");
        }
    }
    return p;
}

Json sphere(PbrtParameters& params, const glm::dmat4& ctm, bool reverse, bool emissive) {
    const double radius = params.real("radius").value_or(1);
    if (!(radius > 0)) params.fail("radius", "must be > 0, got " + show_pbrt_number(radius));
    params.refuse_unused("radius");
    const glm::dmat3 linear(ctm);
    const double s = glm::length(linear[0]);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double expected = i == j ? s * s : 0;
            if (std::abs(glm::dot(linear[i], linear[j]) - expected) > 1e-6 * s * s) {
                throw InputError(params.place() + "Shape \"sphere\": its transform must be a similarity (rotation, "
                                 "uniform scale, mirror, translation): the course's spheres stay round");
            }
        }
    }
    if (reverse && emissive) {
        throw InputError(params.place() + "Shape \"sphere\": ReverseOrientation on an emitting sphere: the course's "
                         "sphere lights emit outward only");
    }
    return {{"type", "sphere"},
            {"center", to_json(checked_point(params, "radius", point_of(ctm, Vec3d(0))))},
            {"radius", radius * s}};
}

// pbrt's front of each triangle: the side of its shading normals N (negated by ReverseOrientation) when
// given, else of its winding (p1 − p0) × (p2 − p0), flipped by ReverseOrientation and by a transform that
// swaps handedness. The course's front is the winding's side, so a triangle whose fronts differ turns.
Json triangle_mesh(PbrtParameters& params, const glm::dmat4& ctm, bool reverse) {
    const std::vector<double> P = params.reals("P", "point3", 3);
    if (P.empty()) params.fail("P", "a trianglemesh needs \"point3 P\"");
    const std::size_t n = P.size() / 3;
    std::vector<int> indices = params.integers("indices");
    if (indices.empty()) {
        if (n != 3) params.fail("P", "without \"integer indices\" a trianglemesh must have exactly 3 points");
        indices = {0, 1, 2};
    }
    if (indices.size() % 3 != 0) params.fail("indices", "must be a multiple of 3, got " + std::to_string(indices.size()));
    for (const int i : indices) {
        if (i < 0 || std::size_t(i) >= n) {
            params.fail("indices", "must be in [0, " + std::to_string(n - 1) + "], got " + std::to_string(i));
        }
    }
    const std::vector<double> N = params.reals("N", "normal", 3);
    const std::vector<double> uv = params.reals("uv", "point2", 2);
    if (!N.empty() && N.size() != P.size()) params.fail("N", "must have one normal per point of P");
    if (!uv.empty() && uv.size() / 2 != n) params.fail("uv", "must have one point2 per point of P");
    params.refuse_unused("P, indices, N, uv");

    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(ctm)));
    const bool swaps = glm::determinant(glm::dmat3(ctm)) < 0;
    std::vector<Vec3d> points(n), normals(N.empty() ? 0 : n);
    Json positions = Json::array(), normals_json = Json::array(), uv_json = Json::array(), triangles = Json::array();
    for (std::size_t i = 0; i < n; ++i) {
        points[i] = checked_point(params, "P", point_of(ctm, {P[3 * i], P[3 * i + 1], P[3 * i + 2]}));
        positions.push_back(to_json(points[i]));
        if (!N.empty()) {
            Vec3d normal = normal_matrix * Vec3d(N[3 * i], N[3 * i + 1], N[3 * i + 2]);
            if (!(glm::length(normal) > 1e-30) || !std::isfinite(glm::length(normal))) {
                params.fail("N", "normal " + std::to_string(i) + " has no direction");
            }
            normals[i] = glm::normalize(reverse ? -normal : normal);
            normals_json.push_back(to_json(normals[i]));
        }
        if (!uv.empty()) uv_json.push_back(Json::array({uv[2 * i], uv[2 * i + 1]}));
    }
    for (std::size_t t = 0; t < indices.size(); t += 3) {
        int a = indices[t], b = indices[t + 1], c = indices[t + 2];
        const Vec3d winding = glm::cross(points[std::size_t(b)] - points[std::size_t(a)],
                                         points[std::size_t(c)] - points[std::size_t(a)]);
        const bool turn = N.empty() ? (reverse != swaps)
                                    : glm::dot(winding, normals[std::size_t(a)] + normals[std::size_t(b)] +
                                                            normals[std::size_t(c)]) < 0;
        if (turn) std::swap(b, c);
        triangles.push_back(Json::array({a, b, c}));
    }
    Json mesh = {{"type", "mesh"}, {"positions", std::move(positions)}, {"triangles", std::move(triangles)}};
    if (!N.empty()) mesh["normals"] = std::move(normals_json);
    if (!uv.empty()) mesh["uv"] = std::move(uv_json);
    return mesh;
}

Json ply_mesh(PbrtParameters& params, const glm::dmat4& ctm, bool reverse, bool emissive) {
    const std::optional<std::string> file = params.string("filename");
    if (!file) params.fail("filename", "a plymesh needs \"string filename\"");
    std::string extension = std::filesystem::path(*file).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".ply") params.fail("filename", "must name a .ply file (the course reads no .ply.gz), got \"" + *file + "\"");
    params.refuse_unused("filename");
    if (reverse && emissive) {
        throw InputError(params.place() + "Shape \"plymesh\": ReverseOrientation on an emitting PLY mesh is not in "
                         "the course (its meshes emit on the side of their winding)");
    }
    Json mesh = {{"type", "mesh"}, {"file", *file}};
    if (ctm != glm::dmat4(1.0)) {
        Json rows = Json::array();
        for (int r = 0; r < 3; ++r) rows.push_back(Json::array({ctm[0][r], ctm[1][r], ctm[2][r], ctm[3][r]}));
        mesh["transform"] = {{"matrix", std::move(rows)}};
    }
    return mesh;
}

}  // namespace

Json shape(const std::string& type, PbrtParameters& params, const glm::dmat4& ctm, bool reverse_orientation,
           bool emissive, const std::string& type_place) {
    if (type == "sphere") return sphere(params, ctm, reverse_orientation, emissive);
    if (type == "trianglemesh") return triangle_mesh(params, ctm, reverse_orientation);
    if (type == "plymesh") return ply_mesh(params, ctm, reverse_orientation, emissive);
    throw InputError(type_place + "shape \"" + type + "\" is not in the course; it reads trianglemesh, plymesh, sphere");
}

Json light(const std::string& type, PbrtParameters& params, const glm::dmat4& ctm, const std::string& type_place) {
    const double scale = params.real("scale").value_or(1);
    if (!(scale >= 0)) params.fail("scale", "must be >= 0, got " + show_pbrt_number(scale));
    const Vec3d from = params.point3("from").value_or(Vec3d(0)), to = params.point3("to").value_or(Vec3d(0, 0, 1));
    Json light;
    if (type == "point" || type == "spot") {
        const Vec3d I = color_in(params, "I", Vec3d(1), kLargestSceneNumber) * scale;
        light = {{"type", type}, {"position", to_json(checked_point(params, "from", point_of(ctm, from)))},
                 {"intensity", to_json(I)}};
        if (type == "spot") {
            const double angle = params.real("coneangle").value_or(30), delta = params.real("conedeltaangle").value_or(5);
            if (!(angle > 0 && angle <= 180)) params.fail("coneangle", "must be in (0, 180]");
            if (!(delta >= 0 && delta <= angle)) params.fail("conedeltaangle", "must be in [0, coneangle]");
            light["at"] = to_json(checked_point(params, "to", point_of(ctm, to)));
            light["cone_angle"] = angle;
            light["cone_delta"] = delta;
        } else if (params.has("to")) {
            params.fail("to", "a point light has no \"to\"");
        }
        params.refuse_unused(type == "spot" ? "I, scale, from, to, coneangle, conedeltaangle" : "I, scale, from");
    } else if (type == "distant") {
        const Vec3d direction = glm::dmat3(ctm) * (to - from);
        if (!(glm::length(direction) > 1e-30)) params.fail("to", "must differ from \"from\"");
        light = {{"type", "distant"}, {"direction", to_json(direction)},
                 {"irradiance", to_json(color_in(params, "L", Vec3d(1), kLargestSceneNumber) * scale)}};
        params.refuse_unused("L, scale, from, to");
    } else if (type == "infinite") {
        if (params.has("filename")) {
            params.fail("filename", "an infinite light with an image is pbrt-v4's equal-area square map, which the "
                                    "course does not read (its environment images are latitude-longitude, in JSON)");
        }
        light = {{"type", "environment"},
                 {"radiance", to_json(color_in(params, "L", Vec3d(1), kLargestSceneNumber) * scale)}};
        params.refuse_unused("L, scale");
    } else {
        throw InputError(type_place + "light \"" + type + "\" is not in the course; it reads point, spot, distant, "
                         "infinite (constant L)");
    }
    return light;
}

}  // namespace rt::pbrt
