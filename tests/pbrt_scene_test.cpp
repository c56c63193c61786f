// The pbrt-v4 reader (common/rt/io/pbrt_reader.hpp): how each directive and parameter type maps onto the
// course's scene, pbrt's camera conventions (fov on the shorter axis, a left-handed camera), the emitting
// side of an area light, and the round trip of cornell.json written by hand as assets/scenes/cornell.pbrt.
// The broken files are in tests/data/bad_scenes (bad_input_test.cpp).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <unistd.h>

#include "01_ray_generation/camera.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "05_recursive_gi/gi_render.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "rt/io/effects.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/pbrt_reader.hpp"
#include "rt/io/scene_loader.hpp"

using namespace rt;
using Catch::Matchers::Contains;

namespace {

namespace fs = std::filesystem;

const std::string kCamera = "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n";

nlohmann::json translated(const std::string& text) {
    return translate_pbrt_text(text, "t.pbrt").scene;
}

Scene loaded(const std::string& text) {
    return read_scene(translated(text), "t.pbrt");
}

std::string error_of(const std::string& text) {
    try {
        loaded(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

Vec3d vec(const nlohmann::json& j) {
    return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

// The sphere the world block's one Shape "sphere" becomes.
SphereShape sphere_of(const std::string& world) {
    const Scene scene = loaded(kCamera + "WorldBegin\n" + world);
    REQUIRE(scene.shapes.size() == 1);
    return std::get<SphereShape>(scene.shapes[0].geometry);
}

// The front of a loaded mesh's first triangle: the side from which its corners turn counter-clockwise.
Vec3 front_of_first_triangle(const Scene& scene) {
    const auto& mesh = std::get<MeshShape>(scene.shapes.at(0).geometry);
    const auto& t = mesh.triangles.at(0);
    return glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
}

RenderResult render(const Scene& scene, int width, int height, int spp) {
    const EffectSet simulated = simulated_effects(scene, kRecursiveChapterEffects);
    const RenderScene prepared(scene, simulated);
    PathOptions options;
    options.simulated = simulated;
    const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, width, height);
    return render_paths(tracer, camera, RenderSettings{width, height, spp, 7, 2, ProgressStyle::kNone});
}

Color mean_of(const Image& image) {
    Color sum(0);
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) sum += image.at(x, y);
    }
    return sum / Real(image.width() * image.height());
}

}  // namespace

TEST_CASE("pbrt transforms compose on the right, as pbrt's: Translate, Scale, Rotate, Transform, ConcatTransform",
          "[pbrt][loader]") {
    SphereShape s = sphere_of("Translate 1 2 3\nScale 2 2 2\nShape \"sphere\" \"float radius\" 0.5\n");
    CHECK(Vec3d(s.center) == Vec3d(1, 2, 3));
    CHECK(s.radius == 1);
    // Rotating 90° about z takes the sphere's offset along x to y (right-handed).
    s = sphere_of("Rotate 90 0 0 1\nTranslate 1 0 0\nShape \"sphere\"\n");
    CHECK(s.center.x == Approx(0).margin(1e-6));
    CHECK(s.center.y == Approx(1));
    // Transform lists the matrix column by column: its last four numbers are the translation.
    s = sphere_of("Transform [1 0 0 0  0 1 0 0  0 0 1 0  4 5 6 1]\nConcatTransform [2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1]\n"
                  "Shape \"sphere\"\n");
    CHECK(Vec3d(s.center) == Vec3d(4, 5, 6));
    CHECK(s.radius == 2);
    // Identity, a named coordinate system, and the attribute stack.
    s = sphere_of("Translate 7 0 0\nCoordinateSystem \"here\"\nIdentity\nAttributeBegin\nTranslate 0 9 0\n"
                  "AttributeEnd\nTransformBegin\nTranslate 0 9 0\nTransformEnd\nCoordSysTransform \"here\"\n"
                  "Shape \"sphere\"\n");
    CHECK(Vec3d(s.center) == Vec3d(7, 0, 0));
}

TEST_CASE("pbrt's Camera, Film and Sampler: fov on the shorter axis, lens, size and samples as defaults",
          "[pbrt][loader]") {
    const std::string lens = "\"float lensradius\" 0.1 \"float focaldistance\" 4";
    nlohmann::json j = translated("Film \"rgb\" \"integer xresolution\" 200 \"integer yresolution\" 100\n"
                                  "Sampler \"halton\" \"integer pixelsamples\" 32\nCamera \"perspective\" "
                                  "\"float fov\" 50 " + lens + "\nWorldBegin\n");
    CHECK(j["camera"]["vfov"] == 50);  // landscape: the shorter side is the height
    CHECK(j["camera"]["aperture"] == 0.1);
    CHECK(j["camera"]["focus_distance"] == 4);
    CHECK(j["image"] == nlohmann::json{{"width", 200}, {"height", 100}, {"spp", 32}});
    j = translated("Film \"rgb\" \"integer xresolution\" 100 \"integer yresolution\" 200\n"
                   "Camera \"perspective\" \"float fov\" 50\nWorldBegin\n");
    // Portrait: fov spans the width, so vfov = 2 atan(tan(25°) · 200 / 100).
    CHECK(j["camera"]["vfov"].get<double>() ==
          Approx(360 / std::numbers::pi * std::atan(std::tan(25 * std::numbers::pi / 180) * 2)));
    // pbrt's defaults: 1280 × 720, fov 90, 16 samples.
    j = translated("WorldBegin\n");
    CHECK(j["image"] == nlohmann::json{{"width", 1280}, {"height", 720}, {"spp", 16}});
    CHECK(j["camera"]["vfov"] == 90);
}

TEST_CASE("pbrt's Integrator maxdepth is the scene's path depth, pbrt's 5 when the file gives none",
          "[pbrt][loader]") {
    CHECK(loaded("Integrator \"path\" \"integer maxdepth\" 3\n" + kCamera + "WorldBegin\n").max_depth == 3);
    CHECK(loaded("Integrator \"volpath\"\n" + kCamera + "WorldBegin\n").max_depth == 5);
    CHECK(loaded(kCamera + "WorldBegin\n").max_depth == 5);
    CHECK_THAT(error_of("Integrator \"path\" \"integer maxdepth\" 1025\n" + kCamera + "WorldBegin\n"),
               Contains("\"integer maxdepth\": must be in [1, 1024]"));
    // The course's own scenes have no depth unless they say so: each chapter's rule then holds.
    CHECK_FALSE(load_scene(scene_path("cornell.json")).max_depth);
}

TEST_CASE("A pbrt camera shows pbrt's picture, not its mirror, in both aspect ratios", "[pbrt][camera]") {
    for (const auto& [width, height] : {std::pair{64, 32}, std::pair{32, 64}}) {
        INFO(width << "x" << height);
        const std::string film = "Film \"rgb\" \"integer xresolution\" " + std::to_string(width) +
                                 " \"integer yresolution\" " + std::to_string(height) + "\n";
        // pbrt's LookAt makes the camera's x axis up × view: looking down -z, world +x is on the left.
        const Scene plain = loaded(film + "LookAt 0 0 0  0 0 -1  0 1 0\nCamera \"perspective\"\nWorldBegin\n");
        const Scene flipped = loaded(film + "Scale -1 1 1\nLookAt 0 0 0  0 0 -1  0 1 0\nCamera \"perspective\"\n"
                                            "WorldBegin\n");
        CHECK(plain.camera.mirrored);
        CHECK_FALSE(flipped.camera.mirrored);
        const PinholeCamera a = make_pinhole_camera(plain.camera, width, height);
        const PinholeCamera b = make_pinhole_camera(flipped.camera, width, height);
        CHECK(film_direction(a, Real(0.25) * Real(width), Real(height) / 2).x > 0);
        CHECK(film_direction(b, Real(0.25) * Real(width), Real(height) / 2).x < 0);
        CHECK(film_direction(a, Real(width) / 2, 0).y > 0);  // the top row looks up in both
        CHECK(film_direction(b, Real(width) / 2, 0).y > 0);
        // fov 90 spans the shorter side: its edge's ray is 45° off the axis.
        const bool landscape = width >= height;
        const Vec3 edge = landscape ? film_direction(a, Real(width) / 2, 0) : film_direction(a, 0, Real(height) / 2);
        CHECK(std::abs(landscape ? edge.y : edge.x) / -edge.z == Approx(1).epsilon(1e-5));
    }
}

TEST_CASE("A pbrt scene renders as its equivalent JSON scene, and not as its mirror image",
          "[pbrt][camera][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable][ex:ch03.robust_offset]"
          "[ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.uniform_cone]"
          "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    // An asymmetric picture: a lamp sphere up and to world +x, a grey sphere down and to -x, seen by pbrt's
    // LookAt (left-handed). The lamp is of pbrt's default material, diffuse grey 0.5, and emits.
    const std::string world = "WorldBegin\nAttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [4 4 4]\n"
                              "Translate 1.5 1 0\nShape \"sphere\" \"float radius\" 0.6\nAttributeEnd\n"
                              "Translate -1 -0.8 0\nShape \"sphere\"\n";
    auto json = [](bool mirrored, const std::string& size) {
        return std::string(R"({"camera": {"from": [0, 0, 6], "at": [0, 0, 0], "vfov": 50, "mirrored": )") +
               (mirrored ? "true" : "false") + "}, " + size +
               R"(, "materials": {"lamp": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5], "emission": [4, 4, 4]},
               "grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
               "shapes": [{"type": "sphere", "center": [1.5, 1, 0], "radius": 0.6, "material": "lamp"},
                          {"type": "sphere", "center": [-1, -0.8, 0], "radius": 1, "material": "grey"}]})";
    };
    for (const auto& [width, height] : {std::pair{48, 32}, std::pair{32, 48}}) {
        INFO(width << "x" << height);
        const std::string film = "Film \"rgb\" \"integer xresolution\" " + std::to_string(width) +
                                 " \"integer yresolution\" " + std::to_string(height) + "\n";
        // pbrt's fov 50 on the shorter side; the JSON's vfov must then be the same angle for a landscape
        // image, and the matching wider one for a portrait image.
        const double vfov = width >= height ? 50 : 360 / std::numbers::pi * std::atan(std::tan(25 * std::numbers::pi / 180) * height / width);
        std::string size = R"("image": {"width": )" + std::to_string(width) + R"(, "height": )" + std::to_string(height) + "}";
        auto json_scene = [&](bool mirrored) {
            std::string text = json(mirrored, size);
            char exact[32];
            std::snprintf(exact, sizeof exact, "%.17g", vfov);
            text.replace(text.find("\"vfov\": 50"), 10, std::string("\"vfov\": ") + exact);
            return parse_scene(text, "same.json");
        };
        const Scene pbrt_scene = loaded(film + "LookAt 0 0 6  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 50\n" + world);
        const Image from_pbrt = render(pbrt_scene, width, height, 16).image;
        const Image same = render(json_scene(true), width, height, 16).image;
        const Image mirror = render(json_scene(false), width, height, 16).image;
        double to_same = 0, to_mirror = 0;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                to_same = std::max(to_same, double(glm::length(from_pbrt.at(x, y) - same.at(x, y))));
                to_mirror = std::max(to_mirror, double(glm::length(from_pbrt.at(x, y) - mirror.at(x, y))));
            }
        }
        CHECK(to_same < 1e-3);
        CHECK(to_mirror > 0.5);
    }
}

TEST_CASE("pbrt materials map onto the course's: diffuse, conductor (spectra, reflectance, roughness), dielectric",
          "[pbrt][loader]") {
    auto material = [](const std::string& m) {
        return translated(kCamera + "WorldBegin\n" + m + "\nShape \"sphere\"\n")["materials"].begin().value();
    };
    CHECK(material("Material \"diffuse\" \"rgb reflectance\" [0.2 0.3 0.4]") ==
          nlohmann::json{{"type", "diffuse"}, {"albedo", {0.2, 0.3, 0.4}}});
    CHECK(material("")["albedo"] == nlohmann::json{0.5, 0.5, 0.5});  // pbrt's default material
    // Silver by name, as Tungsten's table gives it; roughness 0.0625 remapped: α = 0.25, course r = 0.5.
    nlohmann::json m = material("Material \"conductor\" \"spectrum eta\" \"metal-Ag-eta\" \"spectrum k\" "
                                "\"metal-Ag-k\" \"float roughness\" 0.0625");
    CHECK(vec(m["eta"]).x == Approx(0.1552646489));
    CHECK(vec(m["k"]).z == Approx(2.1469504455));
    CHECK(m["roughness"].get<double>() == Approx(0.5));
    // Not remapped: α = 0.01 is given, r = 0.1; below α = 1e-3 it is smooth.
    m = material("Material \"conductor\" \"float uroughness\" 0.01 \"float vroughness\" 0.01 \"bool remaproughness\" false");
    CHECK(m["roughness"].get<double>() == Approx(0.1));
    CHECK(vec(m["eta"]).x == Approx(0.2004376970));  // pbrt's default metal, copper
    CHECK_FALSE(material("Material \"conductor\" \"float roughness\" 1e-7").contains("roughness"));
    // reflectance r: η = 1, k = 2 √r / √(1 − r).
    m = material("Material \"conductor\" \"rgb reflectance\" [0.5 0.5 0.5]");
    CHECK(vec(m["eta"]) == Vec3d(1));
    CHECK(vec(m["k"]).x == Approx(2 * std::sqrt(0.5) / std::sqrt(0.5)));
    m = material("Material \"dielectric\" \"float eta\" 1.33 \"float roughness\" 0.04");
    CHECK(m["type"] == "dielectric");
    CHECK(m["ior"] == 1.33);
    CHECK(m["roughness"].get<double>() == Approx(std::sqrt(0.2)));
    // Named materials, and one material per distinct content under one name.
    const nlohmann::json j = translated(kCamera + "WorldBegin\nMakeNamedMaterial \"m\" \"string type\" \"diffuse\"\n"
                                                  "NamedMaterial \"m\"\nShape \"sphere\"\nAttributeBegin\n"
                                                  "AreaLightSource \"diffuse\" \"rgb L\" [1 2 3] \"float scale\" 2\n"
                                                  "Shape \"sphere\"\nAttributeEnd\n");
    CHECK(j["shapes"][0]["material"] == "m");
    CHECK(j["shapes"][1]["material"] == "m (emitting)");
    CHECK(j["materials"]["m (emitting)"]["emission"] == nlohmann::json{2.0, 4.0, 6.0});
}

TEST_CASE(
    "pbrt's coateddiffuse is the course's smooth coat: reflectance and eta read, what pbrt's layer adds "
    "named or refused",
    "[pbrt][loader]") {
    const std::string world = kCamera + "WorldBegin\n";
    auto material = [&](const std::string& m) {
        return translated(world + m + "\nShape \"sphere\"\n")["materials"].begin().value();
    };
    CHECK(material("Material \"coateddiffuse\" \"rgb reflectance\" [0.2 0.3 0.4] \"float eta\" 1.4") ==
          nlohmann::json{{"type", "coateddiffuse"}, {"albedo", {0.2, 0.3, 0.4}}, {"ior", 1.4}});
    // pbrt's defaults: reflectance 0.5, eta 1.5, a smooth coat; roughness 0 and albedo 0 may be said.
    CHECK(
        material("Material \"coateddiffuse\" \"float roughness\" 0 \"rgb albedo\" [0 0 0] \"float g\" 0.3") ==
        nlohmann::json{{"type", "coateddiffuse"}, {"albedo", {0.5, 0.5, 0.5}}, {"ior", 1.5}});
    // It loads as the course's material; the layer's thickness and the random walk's settings are named.
    const PbrtTranslation t = translate_pbrt_text(
        world +
            "Material \"coateddiffuse\" \"integer maxdepth\" 4 \"integer nsamples\" 2\nShape \"sphere\"\n",
        "t.pbrt");
    const Scene scene = read_scene(t.scene, "t.pbrt");
    CHECK(scene.materials.at(0).type == "coateddiffuse");
    CHECK(scene.materials.at(0).ior == Approx(1.5));
    REQUIRE(t.notes.size() == 3);
    CHECK_THAT(t.notes[0], Contains("\"thickness\" 0.01"));
    CHECK_THAT(t.notes[1], Contains("\"maxdepth\""));
    CHECK_THAT(t.notes[2], Contains("\"nsamples\""));
    // What the course's coat cannot be is refused, with its place.
    CHECK(error_of(world + "Material \"coateddiffuse\" \"float roughness\" 0.1\n") ==
          "t.pbrt:4:26: Material \"coateddiffuse\": \"float roughness\": a rough coat is not in the course: "
          "its "
          "coateddiffuse has a smooth coat (roughness 0, pbrt's default)");
    CHECK_THAT(error_of(world + "Material \"coateddiffuse\" \"rgb albedo\" [0.5 0.5 0.5]\n"),
               Contains("t.pbrt:4:26: Material \"coateddiffuse\": \"rgb albedo\": a scattering layer"));
    CHECK_THAT(error_of(world + "Material \"coateddiffuse\" \"float eta\" 0.9\n"),
               Contains("\"float eta\": must be in [1, 10]"));
    CHECK_THAT(error_of(world + "Material \"coateddiffuse\" \"float displacement\" 1\n"),
               Contains("it reads reflectance, eta, roughness 0"));
}

TEST_CASE("pbrt textures: imagemap and checkerboard on any colour parameter, as the course's textures",
          "[pbrt][loader]") {
    const std::string world = kCamera + "WorldBegin\n";
    auto first_material = [&](const std::string& text) {
        return translated(world + text + "\nShape \"sphere\"\n")["materials"].begin().value();
    };
    // An 8-bit image: sRGB unless said otherwise (pbrt's default), uscale and vscale its repeats.
    const std::string wood =
        (scene_path("cornell.json").parent_path().parent_path() / "textures" / "ch04_wood.png").string();
    nlohmann::json m =
        first_material("Texture \"wood\" \"spectrum\" \"imagemap\" \"string filename\" \"" + wood +
                       "\" \"float uscale\" 2 "
                       "\"float vscale\" 3\nMaterial \"diffuse\" \"texture reflectance\" \"wood\"");
    CHECK(m["albedo"] == nlohmann::json{{"texture", wood},
                                        {"encoding", "srgb"},
                                        {"filter", "bilinear"},
                                        {"wrap", "repeat"},
                                        {"scale", {2.0, 3.0}}});
    CHECK(loaded(world + "Texture \"wood\" \"spectrum\" \"imagemap\" \"string filename\" \"" + wood +
                 "\"\nMaterial \"diffuse\" \"texture reflectance\" \"wood\"\nShape \"sphere\"\n")
              .materials.at(0)
              .textures.size() == 1);
    m = first_material("Texture \"data\" \"spectrum\" \"imagemap\" \"string filename\" \"" + wood +
                       "\" \"string encoding\" "
                       "\"linear\" \"string filter\" \"point\" \"string wrap\" \"clamp\"\n"
                       "Material \"coateddiffuse\" \"texture reflectance\" \"data\"");
    CHECK(m["albedo"]["encoding"] == "linear");
    CHECK(m["albedo"]["filter"] == "nearest");
    CHECK(m["albedo"]["wrap"] == "clamp");
    // A checkerboard: tex1 on the even squares; a float one is grey; on a conductor's index too.
    m = first_material(
        "Texture \"c\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [0.1 0.2 0.3] \"rgb tex2\" [0.9 0.8 0.7] "
        "\"float uscale\" 4 \"float vscale\" 4\nMaterial \"diffuse\" \"texture reflectance\" \"c\"");
    CHECK(m["albedo"] ==
          nlohmann::json{{"checker", {{"even", {0.1, 0.2, 0.3}}, {"odd", {0.9, 0.8, 0.7}}, {"scale", 4.0}}}});
    m = first_material(
        "Texture \"g\" \"spectrum\" \"checkerboard\"\nMaterial \"conductor\" \"texture eta\" \"g\"");
    CHECK(m["eta"] ==
          nlohmann::json{{"checker", {{"even", {1.0, 1.0, 1.0}}, {"odd", {0.0, 0.0, 0.0}}, {"scale", 1.0}}}});
    // The course loads it and shades the checker: the scene's material holds the texture.
    const Scene scene = loaded(world +
                               "Texture \"c\" \"spectrum\" \"checkerboard\" \"rgb tex2\" [0.5 0.5 0.5]\n"
                               "Material \"diffuse\" \"texture reflectance\" \"c\"\nShape \"sphere\"\n");
    REQUIRE(scene.materials.at(0).textures.size() == 1);
    CHECK(scene.materials[0].textures[0].parameter == &Material::albedo);
    // What the course's textures cannot be is refused at its place.
    CHECK(error_of(world + "Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \"sky.exr\"\n") ==
          "t.pbrt:4:35: Texture \"t\": \"string filename\": the course's textures are 8-bit PNG or JPEG "
          "images (float "
          "EXR, PFM and HDR images and TGA are not in the course), got \"sky.exr\"");
    CHECK(error_of(world + "Material \"diffuse\" \"texture reflectance\" \"none\"\n") ==
          "t.pbrt:4:20: Material \"diffuse\": \"texture reflectance\": unknown texture \"none\" (a Texture "
          "directive "
          "defines it)");
    CHECK_THAT(
        error_of(
            world +
            "Texture \"f\" \"float\" \"checkerboard\"\nMaterial \"diffuse\" \"texture reflectance\" \"f\"\n"),
        Contains(
            "t.pbrt:5:20: Material \"diffuse\": \"texture reflectance\": texture \"f\" is a float texture"));
    CHECK_THAT(error_of(world + "Texture \"c\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [2 2 2]\n"
                                "Material \"diffuse\" \"texture reflectance\" \"c\"\n"),
               Contains("texture \"c\": its values must be in [0, 1] here"));
    CHECK_THAT(error_of(world + "Texture \"c\" \"spectrum\" \"checkerboard\" \"float uscale\" 2\n"),
               Contains("t.pbrt:4:39: Texture \"c\": \"float uscale\": uscale and vscale must be equal"));
    CHECK_THAT(
        error_of(world + "Texture \"c\" \"spectrum\" \"marble\"\n"),
        Contains("t.pbrt:4:1: texture \"marble\" is not in the course; it reads imagemap, checkerboard"));
}

TEST_CASE("A pbrt blackbody is RGB of luminance 1: at 2856 K the chromaticity of CIE illuminant A",
          "[pbrt][loader]") {
    const nlohmann::json j = translated(kCamera +
                                        "WorldBegin\nAreaLightSource \"diffuse\" \"blackbody L\" 2856 "
                                        "\"float scale\" 3\nShape \"sphere\"\n");
    const Vec3d rgb = vec(j["materials"].begin().value()["emission"]) / 3.0;
    // Linear sRGB to CIE XYZ (IEC 61966-2-1).
    const double X = 0.4124564 * rgb.x + 0.3575761 * rgb.y + 0.1804375 * rgb.z;
    const double Y = 0.2126729 * rgb.x + 0.7151522 * rgb.y + 0.0721750 * rgb.z;
    const double Z = 0.0193339 * rgb.x + 0.1191920 * rgb.y + 0.9503041 * rgb.z;
    CHECK(Y == Approx(1).margin(1e-5));
    CHECK(X / (X + Y + Z) == Approx(0.44757).margin(1e-3));  // illuminant A, a blackbody of 2856 K
    CHECK(Y / (X + Y + Z) == Approx(0.40745).margin(1e-3));
    // Hotter is bluer; below about 1900 K blue leaves the sRGB gamut, clipped to 0.
    const Vec3d hot = vec(translated(
        kCamera + "WorldBegin\nLightSource \"point\" \"blackbody I\" 10000\n")["lights"][0]["intensity"]);
    CHECK(hot.z > hot.x);
    const Vec3d cold = vec(translated(
        kCamera + "WorldBegin\nLightSource \"point\" \"blackbody I\" 1667\n")["lights"][0]["intensity"]);
    CHECK(cold.z == 0);
    CHECK(error_of(kCamera + "WorldBegin\nLightSource \"point\" \"blackbody I\" 1000\n") ==
          "t.pbrt:4:21: LightSource \"point\": \"blackbody I\": must be in [1667, 25000] kelvin (the range "
          "of the "
          "course's conversion), got 1000");
}

TEST_CASE("pbrt lights map onto the course's: point, spot, distant, a constant infinite light", "[pbrt][loader]") {
    const nlohmann::json j = translated(
        kCamera + "WorldBegin\nTranslate 0 1 0\n"
                  "LightSource \"point\" \"rgb I\" [1 2 3] \"float scale\" 2 \"point3 from\" [1 0 0]\n"
                  "LightSource \"spot\" \"point3 from\" [0 5 0] \"point3 to\" [0 0 0] \"float coneangle\" 20 "
                  "\"float conedeltaangle\" 4\n"
                  "LightSource \"distant\" \"point3 from\" [0 0 0] \"point3 to\" [0 -1 0] \"rgb L\" [3 3 3]\n"
                  "LightSource \"infinite\" \"rgb L\" [0.1 0.2 0.3]\n");
    const nlohmann::json& lights = j["lights"];
    REQUIRE(lights.size() == 4);
    CHECK(lights[0] == nlohmann::json{{"type", "point"}, {"position", {1.0, 1.0, 0.0}}, {"intensity", {2.0, 4.0, 6.0}}});
    CHECK(vec(lights[1]["position"]) == Vec3d(0, 6, 0));
    CHECK(vec(lights[1]["at"]) == Vec3d(0, 1, 0));
    CHECK(lights[1]["cone_angle"] == 20);
    CHECK(lights[1]["cone_delta"] == 4);
    CHECK(lights[2] == nlohmann::json{{"type", "distant"}, {"direction", {0.0, -1.0, 0.0}}, {"irradiance", {3.0, 3.0, 3.0}}});
    CHECK(lights[3] == nlohmann::json{{"type", "environment"}, {"radiance", {0.1, 0.2, 0.3}}});
}

TEST_CASE("pbrt parameter types: with or without brackets, bool as word or string, comments, pbrt-v3 names",
          "[pbrt][loader]") {
    const nlohmann::json j = translated(
        "# a comment\nFilm \"rgb\" \"integer xresolution\" [ 10 ] \"integer yresolution\" 20 # another\n" + kCamera +
        "WorldBegin\nMaterial \"conductor\" \"bool remaproughness\" false \"float roughness\" 0.25\n"
        "Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0] \"normal N\" [0 0 1 0 0 1 0 0 1] "
        "\"point2 uv\" [0 0 1 0 0 1]\n"
        "Material \"conductor\" \"bool remaproughness\" \"false\" \"float roughness\" 0.25\nShape \"sphere\"\n");
    CHECK(j["image"]["width"] == 10);
    CHECK(j["image"]["height"] == 20);
    const nlohmann::json& mesh = j["shapes"][0];
    CHECK(mesh["triangles"] == nlohmann::json{{0, 1, 2}});  // three points need no indices
    CHECK(mesh["uv"] == nlohmann::json{{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}});
    CHECK(mesh["normals"].size() == 3);
    for (const auto& m : j["materials"]) CHECK(m["roughness"].get<double>() == Approx(0.5));
    CHECK_THAT(error_of(kCamera + "WorldBegin\nShape \"sphere\" \"float radius\" [1 2]\n"),
               Contains("t.pbrt:4:16: Shape \"sphere\": \"float radius\": must be one number, got 2"));
}

TEST_CASE("An area light emits on pbrt's side: its normals' when given, else its winding's, flipped by "
          "ReverseOrientation and by a mirroring transform", "[pbrt][emission]") {
    const std::string lamp = "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n";
    const std::string down = "Shape \"trianglemesh\" \"point3 P\" [0 1 0  1 1 0  1 1 1]";  // winding: -y
    auto front = [&](const std::string& before, const std::string& normals) {
        return front_of_first_triangle(loaded(kCamera + "WorldBegin\n" + lamp + before + down + normals + "\n")).y;
    };
    CHECK(front("", "") < 0);
    CHECK(front("ReverseOrientation\n", "") > 0);
    CHECK(front("Scale 1 -1 1\n", "") > 0);  // the mirror image of a lamp facing down faces up
    CHECK(front("ReverseOrientation\nScale 1 -1 1\n", "") < 0);
    const std::string up = " \"normal N\" [0 1 0  0 1 0  0 1 0]";
    CHECK(front("", up) > 0);
    CHECK(front("ReverseOrientation\n", up) < 0);
    CHECK(front("Scale 1 -1 1\n", up) < 0);  // the normals follow the transform
    // Spheres emit outward only: a reversed one is refused.
    CHECK_THAT(error_of(kCamera + "WorldBegin\n" + lamp + "ReverseOrientation\nShape \"sphere\"\n"),
               Contains("t.pbrt:6:1: Shape \"sphere\": ReverseOrientation on an emitting sphere"));
}

TEST_CASE(
    "A twosided pbrt area light's shapes emit on both sides (the material's two_sided), a sphere's refused",
    "[pbrt][emission]") {
    const std::string mesh =
        "Shape \"trianglemesh\" \"point3 P\" [0 1 0  1 1 0  1 1 1] \"integer indices\" [0 1 2]\n";
    auto lamp = [&](const std::string& sides) {
        return kCamera + "WorldBegin\nAreaLightSource \"diffuse\" \"rgb L\" [2 2 2]" + sides + "\n";
    };
    const Scene two = loaded(lamp(" \"bool twosided\" true") + mesh);
    REQUIRE(two.materials.size() == 1);
    CHECK(two.materials[0].two_sided);
    CHECK(two.materials[0].emission == Color(2));
    CHECK_FALSE(loaded(lamp(" \"bool twosided\" false") + mesh).materials[0].two_sided);
    CHECK_FALSE(loaded(lamp("") + mesh).materials[0].two_sided);
    CHECK_THAT(error_of(lamp(" \"bool twosided\" true") + "Shape \"sphere\"\n"),
               Contains("t.pbrt:5:1: Shape \"sphere\" under a twosided AreaLightSource"));
}

TEST_CASE("Include reads a file from the main scene's folder, and the ignored parameters are named once",
          "[pbrt][loader]") {
    const fs::path folder = fs::temp_directory_path() / ("pbrt_scene_test_" + std::to_string(getpid()));
    fs::create_directories(folder / "parts");
    std::ofstream(folder / "main.pbrt") << "Sampler \"sobol\"\nPixelFilter \"gaussian\" \"float sigma\" 0.5\n"
                                        << kCamera << "WorldBegin\nInclude \"parts/ball.pbrt\"\n";
    std::ofstream(folder / "parts" / "ball.pbrt") << "Shape \"sphere\" \"float radius\" 3\n";
    const Scene scene = load_scene(folder / "main.pbrt");
    CHECK(std::get<SphereShape>(scene.shapes.at(0).geometry).radius == 3);
    REQUIRE(scene.notes.size() == 2);
    CHECK_THAT(scene.notes[0], Contains("Sampler \"sobol\""));
    CHECK_THAT(scene.notes[1], Contains("PixelFilter \"gaussian\""));
    REQUIRE(scene.inputs.size() == 2);  // the scene, then its part: no output may overwrite either
    CHECK(scene.inputs[1].path == folder / "parts/ball.pbrt");
    fs::remove_all(folder);
}

TEST_CASE("cornell.pbrt, cornell.json written by hand in pbrt-v4 form, renders the same image",
          "[pbrt][round_trip][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.slab_test][ex:ch02.slab_widening][ex:ch02.wide_bvh_traversal]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light][ex:ch04.uniform_triangle]"
          "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    const Scene json = load_scene(scene_path("cornell.json"));
    const Scene pbrt = load_scene(scene_path("cornell.pbrt"));
    CHECK(glm::length(pbrt.camera.from - json.camera.from) < 1e-3);
    CHECK(glm::length(pbrt.camera.at - pbrt.camera.from) == Approx(1));
    CHECK_FALSE(pbrt.camera.mirrored);
    CHECK(pbrt.camera.vfov == json.camera.vfov);
    CHECK(pbrt.image.width == json.image.width);
    CHECK(pbrt.image.spp == json.image.spp);
    const int size = 48, spp = 256;
    const Image a = render(json, size, size, spp).image, b = render(pbrt, size, size, spp).image;
    // The same picture within noise: every channel's mean, and each 12 × 12 block's.
    const Color mean_a = mean_of(a), mean_b = mean_of(b);
    for (int c = 0; c < 3; ++c) CHECK(double(mean_b[c]) == Approx(double(mean_a[c])).epsilon(0.01));
    for (int by = 0; by < size; by += 12) {
        for (int bx = 0; bx < size; bx += 12) {
            Color sa(0), sb(0);
            for (int y = by; y < by + 12; ++y) {
                for (int x = bx; x < bx + 12; ++x) {
                    sa += a.at(x, y);
                    sb += b.at(x, y);
                }
            }
            INFO("block at " << bx << ", " << by);
            CHECK(double(sb.r + sb.g + sb.b) == Approx(double(sa.r + sa.g + sa.b)).epsilon(0.05));
        }
    }
}
