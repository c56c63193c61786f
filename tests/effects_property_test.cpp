// The course's promise "only the effects a scene calls for are simulated", checked as a property: for every
// shipped scene and for 400 scenes drawn at random from the scene format, a chapter's render with what
// run_chapter() simulates, simulated_effects(scene, supported) = needed(scene) ∩ supported, gives the same
// image within noise as its render with everything it supports (narrowed by the scene's "effects" list when
// it has one: the list is the user's choice, printed by the run). Chapters 03 (point lights), 04 (direct
// light, stand-ins for mirrors and glass), 07 (paths, dielectrics) and 09 (media) render each scene as their
// executables do; chapter 08 as its light tracer, chapter 10 its path loop before the denoiser (a filter
// whose pixels are not independent, which the comparison assumes), chapter 11 its compute shader where OpenGL
// is there (RT_EFFECTS_ON_GPU; once built, a missing context is said and skipped). Besides the shipped
// scenes, those of tests/data/effects_scenes: what went wrong there once (issue 43).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "03_shadow_rays/shadow_render.hpp"
#include "04_direct_lighting/direct_render.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "07_bsdf_refraction/refraction_materials.hpp"
#include "08_forward_tracing/camera_importance.hpp"
#include "08_forward_tracing/forward_flags.hpp"
#include "08_forward_tracing/light_tracer.hpp"
#include "09_participating_media/media_materials.hpp"
#include "09_participating_media/tracer_choice.hpp"
#include "09_participating_media/volume_path_tracer.hpp"
#include "10_denoising/feature_buffers.hpp"
#ifdef RT_EFFECTS_ON_GPU
#include "11_gpu_shaders/gpu_render.hpp"
#endif
#include "rt/core/conductor_presets.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/material_kind.hpp"
#include "rt/core/random.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"

using namespace rt;

namespace {

struct Chapter {
    const char* name;
    EffectSet supported;
    std::function<Image(const Scene&, const EffectSet&, const RenderSettings&)> render;
};

const std::vector<Chapter>& chapters() {
    static const std::vector<Chapter> list = {
        {"ch03", kShadowChapterEffects,
         [](const Scene& scene, const EffectSet& simulated, const RenderSettings& settings) {
             const World world(scene);
             const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
             return render_shadows(world, scene, camera, shadow_options(simulated, RayOffset{}), settings)
                 .image;
         }},
        {"ch04", kDirectChapterEffects,
         [](const Scene& scene, const EffectSet& simulated, const RenderSettings& settings) {
             DirectOptions options;
             options.simulated = simulated;
             const World world(scene);
             const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
             const MaterialTable materials(scene, simulated);
             const DirectLighting shading(world, materials, collect_lights(scene), options);
             return render_direct(shading, camera, settings, FilmPoints::kStratified).image;
         }},
        {"ch07", kRefractionChapterEffects,
         [](const Scene& scene, const EffectSet& simulated, const RenderSettings& settings) {
             return render_with(choose_renderer(simulated), scene, simulated, settings, {},
                                refraction_materials())
                 .image;
         }},
        {"ch08", kForwardChapterEffects,
         [](const Scene& scene, const EffectSet& simulated, const RenderSettings& settings) {
             const RenderScene prepared(scene, simulated, refraction_materials(Transport::kImportance));
             const LightTracer tracer(prepared.world, prepared.materials, prepared.lights,
                                      light_tracing_camera(scene, settings.width, settings.height),
                                      ForwardFlags{}.light_tracer(simulated));
             return render_light_tracing(tracer, settings, paths_per_image(settings)).render.image;
         }},
        {"ch09", kMediaChapterEffects,
         [](const Scene& scene, const EffectSet& simulated, const RenderSettings& settings) {
             // As the executable renders: the tracer it chooses for the scene (tracer_choice.hpp).
             return render_by_choice(TracerRule::kAuto, {scene, settings, simulated}, {}, {}).result.image;
         }},
        {"ch10", kMediaChapterEffects,
         [](const Scene& scene, const EffectSet& simulated, const RenderSettings& settings) {
             PathOptions options;
             options.simulated = simulated;
             return render_features(scene, settings, options).result.image;
         }},
    };
    return list;
}

#ifdef RT_EFFECTS_ON_GPU
// The OpenGL context, made once; none where this machine offers no OpenGL (chapter 11 is then left out).
const GlContext* gpu() {
    static const std::unique_ptr<GlContext> context = []() -> std::unique_ptr<GlContext> {
        try {
            return std::make_unique<GlContext>(EglPlatform::kAuto);
        } catch (const GlUnavailable& e) {
            WARN("chapter 11 left out: " << e.what());
            return nullptr;
        }
    }();
    return context.get();
}
#endif

// The chapters above, and chapter 11's compute shader where OpenGL is there.
std::vector<Chapter> chapters_here() {
    std::vector<Chapter> list = chapters();
#ifdef RT_EFFECTS_ON_GPU
    if (gpu()) {
        list.push_back(
            {"ch11", kGpuChapterEffects,
             [](const Scene& scene, const EffectSet& simulated, const RenderSettings& settings) {
                 return GpuRenderer(*gpu(), scene, simulated, ShaderKind::kCompute).render(settings).image;
             }});
    }
#endif
    return list;
}

RenderSettings tiny_settings() {
    RenderSettings s;
    s.width = 16, s.height = 12, s.samples_per_pixel = 16, s.seed = 7, s.threads = 1;
    s.progress = ProgressStyle::kNone;
    return s;
}

// Whether two renders of one scene agree within noise, and if not, how they differ. Per channel, the pixels'
// differences a − b have mean 0 when both renders estimate the same image (each pixel's samples are
// independent of every other pixel's): their mean must lie within 5 standard errors of 0, the error taken
// from their scatter. Renders that draw the same random numbers are bit-identical and differ by nothing.
std::string difference(const Image& a, const Image& b) {
    const double n = double(a.width()) * double(a.height());
    std::string found;
    for (int c = 0; c < 3; ++c) {
        double sum = 0, sum2 = 0, scale = 0;
        for (int y = 0; y < a.height(); ++y) {
            for (int x = 0; x < a.width(); ++x) {
                const double d = double(a.at(x, y)[c]) - double(b.at(x, y)[c]);
                sum += d;
                sum2 += d * d;
                scale = std::max({scale, std::abs(double(a.at(x, y)[c])), std::abs(double(b.at(x, y)[c]))});
            }
        }
        const double mean = sum / n;
        const double error = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
        // Float rounding alone (renders of one sum taken in another order) stays below 1e-5 of the image.
        if (std::abs(mean) > 5 * error + 1e-5 * scale) {
            std::ostringstream out;
            out << "channel " << c << ": mean difference " << mean << " against a standard error " << error
                << "; ";
            found += out.str();
        }
    }
    return found;
}

// Renders `scene` in each chapter with what it simulates and with all it supports; checks the two agree.
// Returns how many of those renders differed in their effects (and so were compared).
int check_scene(const Scene& scene, const std::string& shown) {
    int compared = 0;
    static const std::vector<Chapter> every = chapters_here();
    for (const Chapter& chapter : every) {
        const EffectSet simulated = simulated_effects(scene, chapter.supported);
        const EffectSet everything = scene.effects ? chapter.supported & *scene.effects : chapter.supported;
        if (simulated == everything) continue;  // the same function of the same arguments
        ++compared;
        const RenderSettings settings = tiny_settings();
        const Image a = chapter.render(scene, simulated, settings);
        const Image b = chapter.render(scene, everything, settings);
        INFO(chapter.name << " simulated " << simulated.to_string() << " against " << everything.to_string()
                          << ", scene " << shown);
        CHECK(difference(a, b) == "");
    }
    return compared;
}

// A scene drawn at random from the scene format: 0 to 6 shapes (spheres, quads, triangles, boxes, planes) in
// front of the camera, of materials of every type (emissive or not, black or not; dielectrics, which take no
// emission, with and without a medium inside), point lights, the environment, fog between the shapes and an
// "effects" list, each or none.
class SceneDraw {
  public:
    explicit SceneDraw(std::uint64_t seed) : rng_(seed, 17) {}

    std::string text() {
        std::ostringstream s;
        s << R"({"camera": {"from": [0, 0.5, 6], "at": [0, 0, 0], "vfov": 50})";
        const int materials = chance(0.1) ? 0 : 1 + whole(3);
        const int shapes = materials == 0 ? 0 : materials + whole(2);
        if (materials > 0) {
            s << R"(, "materials": {)";
            for (int i = 0; i < materials; ++i) s << (i ? ", " : "") << "\"m" << i << "\": " << material();
            s << "}, \"shapes\": [";
            for (int i = 0; i < shapes; ++i) s << (i ? ", " : "") << shape(i % materials);
            s << "]";
        }
        std::vector<std::string> lights;
        if (chance(0.5))
            lights.push_back(R"({"type": "point", "position": )" + point(-3, 3) + R"(, "intensity": )" +
                             colour(0, 30) + "}");
        if (chance(0.4)) lights.push_back(R"({"type": "environment", "radiance": )" + colour(0, 1.5) + "}");
        if (!lights.empty()) {
            s << R"(, "lights": [)";
            for (std::size_t i = 0; i < lights.size(); ++i) s << (i ? ", " : "") << lights[i];
            s << "]";
        }
        if (chance(0.3)) s << R"(, "medium": )" << medium(0.05, 0.2, 0.4);
        if (chance(0.15)) {
            s << R"(, "effects": [)";
            bool first = true;
            for (std::string_view name : kEffectNames) {
                if (chance(0.6)) continue;
                s << (first ? "" : ", ") << '"' << name << '"';
                first = false;
            }
            s << "]";
        }
        s << "}";
        return s.str();
    }

  private:
    bool chance(double p) { return rng_.next_real() < Real(p); }
    int whole(int n) { return int(rng_.next_uint() % std::uint32_t(n + 1)); }  // 0 … n
    double number(double lo, double hi) { return lo + (hi - lo) * double(rng_.next_real()); }
    std::string triple(double lo, double hi) {
        std::ostringstream s;
        s << "[" << number(lo, hi) << ", " << number(lo, hi) << ", " << number(lo, hi) << "]";
        return s.str();
    }
    std::string point(double lo, double hi) { return triple(lo, hi); }
    // Black a time in five, so that a material that reflects nothing is drawn too.
    std::string colour(double lo, double hi) { return chance(0.2) ? "[0, 0, 0]" : triple(lo, hi); }
    // A medium; `least_absorption` > 0 ends every walk (fog between the shapes has no boundary to leave by).
    std::string medium(double least_absorption, double absorbs, double scatters) {
        std::ostringstream s;
        const std::string sigma_a =
            least_absorption > 0 ? triple(least_absorption, absorbs) : colour(0, absorbs);
        s << R"({"sigma_a": )" << sigma_a << R"(, "sigma_s": )" << colour(0, scatters) << R"(, "g": )"
          << number(-0.8, 0.8) << "}";
        return s.str();
    }
    std::string material() {
        std::ostringstream s;
        const std::string type = course_material_kinds()[std::size_t(whole(5))].type;
        s << R"({"type": ")" << type << '"';
        if (type == "mirror") s << R"(, "reflectance": )" << colour(0, 1);
        if (type == "diffuse" || type == "glossy" || type == "retroreflective")
            s << R"(, "albedo": )" << colour(0, 1);
        if (type == "glossy" || type == "retroreflective") s << R"(, "roughness": )" << number(0.05, 1);
        if (type == "dielectric") {
            s << R"(, "ior": )" << (chance(0.4) ? 1.0 : number(1.1, 2));
            if (chance(0.3)) s << R"(, "roughness": )" << number(0.05, 0.8);
            if (chance(0.5)) {
                s << R"(, "medium": )" << medium(0, 0.5, 3);
            } else if (chance(0.3)) {
                s << R"(, "absorption": )" << colour(0, 1);
            }
        }
        if (type == "conductor") {
            if (chance(0.5)) {
                s << R"(, "preset": ")" << kConductorPresetNames[std::size_t(whole(2))] << '"';
            } else {
                s << R"(, "eta": )" << triple(0.05, 3) << R"(, "k": )" << colour(0, 5);
            }
            if (chance(0.6)) s << R"(, "roughness": )" << number(0, 1);
        }
        if (type != "dielectric" && chance(0.2)) s << R"(, "emission": )" << colour(0, 4);
        s << "}";
        return s.str();
    }
    std::string shape(int material) {
        std::ostringstream s;
        const std::string used = R"(, "material": "m)" + std::to_string(material) + "\"}";
        switch (whole(4)) {
            case 0:
                s << R"({"type": "sphere", "center": )" << point(-1.5, 1.5) << R"(, "radius": )"
                  << number(0.2, 1.5) << used;
                break;
            case 1:
                s << R"({"type": "quad", "origin": )" << point(-2, 0) << R"(, "u": )" << point(0.5, 3)
                  << R"(, "v": [0, )" << number(0.5, 3) << ", " << number(-1, 1) << "]" << used;
                break;
            case 2:
                s << R"({"type": "triangle", "vertices": [)" << point(-2, 2) << ", " << point(-2, 2) << ", "
                  << point(-2, 2) << "]" << used;
                break;
            case 3:
                s << R"({"type": "box", "min": )" << point(-2, -0.5) << R"(, "max": )" << point(0, 2) << used;
                break;
            default:
                s << R"({"type": "plane", "point": [0, -1.5, 0], "normal": [0, 1, 0])" << used;
        }
        return s.str();
    }

    Pcg32 rng_;
};

}  // namespace

TEST_CASE("Every shipped scene renders the same, within noise, with needed ∩ supported as with all supported",
          "[effects][property][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch02.quad_packet]"
          "[ex:ch02.slab_widening][ex:ch02.sphere_stable][ex:ch02.wide_bvh_traversal]"
          "[ex:ch03.lambert_radiance][ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch07.fresnel_conductor]"
          "[ex:ch04.cone_solid_angle][ex:ch04.cosine_hemisphere][ex:ch04.direct_light][ex:ch04.glossy]"
          "[ex:ch04.lambert][ex:ch04.mirror][ex:ch04.power_cosine][ex:ch04.power_cosine_pdf]"
          "[ex:ch04.retroreflective][ex:ch04.sample_quad_light][ex:ch04.uniform_cone][ex:ch05.termination]"
          "[ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch06.uniform_sphere][ex:ch07.beer_lambert]"
          "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract][ex:ch09.free_flight]"
          "[ex:ch09.hg_sample][ex:ch09.transmittance][ex:ch09.volume_vertex]"
          "[ex:ch08.connect][ex:ch08.pinhole_importance][ex:ch08.project_direction]"
          "[ex:ch11.bvh_traversal][ex:ch11.next_real][ex:ch11.pcg32]") {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(assets_dir() / "scenes")) {
        if (entry.path().extension() != ".json") continue;
        const Scene scene = load_scene(entry.path());
        check_scene(scene, entry.path().filename().string());
        ++scenes;
    }
    CHECK(scenes >= 20);
}

// A point light of 1e9 at 1e-4 above a white floor, seen from straight above through a field of view so
// narrow that every pixel looks at the spot below the light: (1/π) · I / h² = 1e9 / (π 1e-8) ≈ 3.18e16.
constexpr const char* kBrightFloor = R"({"camera": {"from": [0, 5e-4, 0], "at": [0, 0, 0], "up": [0, 0, 1],
    "vfov": 1e-3},
  "materials": {"white": {"type": "diffuse", "albedo": [1, 1, 1]}},
  "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"}],
  "lights": [{"type": "point", "position": [0, 1e-4, 0], "intensity": [1e9, 1e9, 1e9]}]})";

TEST_CASE("A point light of 1e9 at 1e-4 above a white floor renders 1e9 / (π 1e-8) in every chapter, unclamped",
          "[effects][property][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane]"
          "[ex:ch03.lambert_radiance]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.direct_light]"
          "[ex:ch04.lambert][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]"
          "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract][ex:ch09.free_flight]"
          "[ex:ch09.transmittance][ex:ch09.volume_vertex][ex:ch08.connect][ex:ch08.pinhole_importance]"
          "[ex:ch08.project_direction][ex:ch11.bvh_traversal][ex:ch11.next_real][ex:ch11.pcg32]") {
    const Scene scene = parse_scene(kBrightFloor, "bright_floor.json");
    check_scene(scene, "bright_floor.json");
    const double exact = 1e9 / (std::numbers::pi * 1e-8);
    for (const Chapter& chapter : chapters_here()) {
        // Chapter 08 traces from the light: a pixel this narrow gets its light only now and then (its
        // estimate is compared, within noise, in the data scenes' test below).
        if (std::string(chapter.name) == "ch08") continue;
        const Image image = chapter.render(scene, simulated_effects(scene, chapter.supported), tiny_settings());
        double lowest = exact, highest = exact;
        for (const Color& pixel : image.pixels()) {
            for (int c = 0; c < 3; ++c) {
                lowest = std::min(lowest, double(pixel[c]));
                highest = std::max(highest, double(pixel[c]));
            }
        }
        INFO(chapter.name << ": pixels from " << lowest << " to " << highest << ", exactly " << exact);
        CHECK(lowest > exact * (1 - 1e-5));
        CHECK(highest < exact * (1 + 1e-5));
    }
}

// The exercises every property test below reaches (it renders with every chapter); a test adds those that
// only its scenes reach. A macro, so that a tag can follow it.
#define EVERY_EXERCISE_TAGS \
    "[effects][property][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch02.quad_packet]" \
    "[ex:ch02.slab_widening][ex:ch02.sphere_stable][ex:ch02.triangle_watertight]" \
    "[ex:ch02.wide_bvh_traversal]" \
    "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cone_solid_angle][ex:ch04.cosine_hemisphere]" \
    "[ex:ch04.direct_light][ex:ch04.glossy][ex:ch04.lambert][ex:ch04.mirror][ex:ch04.power_cosine]" \
    "[ex:ch04.power_cosine_pdf][ex:ch04.retroreflective][ex:ch04.sample_quad_light][ex:ch04.uniform_cone]" \
    "[ex:ch04.uniform_triangle][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]" \
    "[ex:ch06.uniform_sphere][ex:ch07.beer_lambert][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact]" \
    "[ex:ch07.refract][ex:ch09.free_flight][ex:ch09.hg_sample][ex:ch09.transmittance]" \
    "[ex:ch09.volume_vertex]" \
    "[ex:ch08.connect][ex:ch08.pinhole_importance][ex:ch08.project_direction]" \
    "[ex:ch11.bvh_traversal][ex:ch11.next_real][ex:ch11.pcg32]"

TEST_CASE("The scenes of tests/data/effects_scenes render the same with needed ∩ supported as with all",
          EVERY_EXERCISE_TAGS) {
    int scenes = 0;
    const std::filesystem::path folder = std::filesystem::path(RT_TESTS_DIR) / "data" / "effects_scenes";
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".json") continue;
        check_scene(load_scene(entry.path()), entry.path().filename().string());
        ++scenes;
    }
    CHECK(scenes >= 3);
}

TEST_CASE("400 random scenes render the same, within noise, with needed ∩ supported as with all supported",
          EVERY_EXERCISE_TAGS "[ex:ch03.lambert_radiance][ex:ch07.fresnel_conductor]") {
    int compared = 0;
    for (std::uint64_t i = 0; i < 400; ++i) {
        const std::string text = SceneDraw(i).text();
        const Scene scene = parse_scene(text, "random_" + std::to_string(i) + ".json");
        compared += check_scene(scene, text);
    }
    // Most draws leave some supported effect unneeded, so most renders are compared.
    CHECK(compared >= 400);
}
