// Tests of chapter 08: light paths from the lights, the camera's importance, the connection to the pinhole
// (it converges to chapter 06's image), the lens aperture, deterministic splatting, ray counts by kind.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>
#include <variant>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "04_direct_lighting/brdf.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "06_monte_carlo/warp_pdfs.hpp"
#include "07_bsdf_refraction/refraction_materials.hpp"
#include "08_forward_tracing/camera_caustic_cut.hpp"
#include "08_forward_tracing/camera_importance.hpp"
#include "08_forward_tracing/combined_render.hpp"
#include "08_forward_tracing/forward_study.hpp"
#include "08_forward_tracing/light_emission.hpp"
#include "08_forward_tracing/light_tracer.hpp"
#include "08_forward_tracing/splat_render.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/render/interrupt.hpp"
#include "support/chi_square.hpp"

using namespace rt;

namespace {

RenderSettings settings_of(int width, int height, int spp, std::uint64_t seed, int threads = 2) {
    RenderSettings s;
    s.width = width;
    s.height = height;
    s.samples_per_pixel = spp;
    s.seed = seed;
    s.threads = threads;
    s.progress = ProgressStyle::kNone;
    return s;
}

Scene scene_from(const std::string& json) {
    return parse_scene(json, "test.json");
}

// A closed room lit by a point light: floor, walls and ceiling of a 4×3×4 box, the camera inside it.
const char* kPointLightRoom = R"({
  "camera": {"from": [0, 1.5, 1.8], "at": [0, 1.2, -2], "up": [0, 1, 0], "vfov": 70},
  "materials": {"white": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]},
                "red": {"type": "diffuse", "albedo": [0.7, 0.1, 0.1]}},
  "shapes": [
    {"type": "quad", "origin": [-2, 0, 2], "u": [4, 0, 0], "v": [0, 0, -4], "material": "white"},
    {"type": "quad", "origin": [-2, 3, -2], "u": [4, 0, 0], "v": [0, 0, 4], "material": "white"},
    {"type": "quad", "origin": [-2, 0, -2], "u": [4, 0, 0], "v": [0, 3, 0], "material": "red"},
    {"type": "quad", "origin": [-2, 0, 2], "u": [0, 0, -4], "v": [0, 3, 0], "material": "white"},
    {"type": "quad", "origin": [2, 0, -2], "u": [0, 0, 4], "v": [0, 3, 0], "material": "white"},
    {"type": "quad", "origin": [2, 0, 2], "u": [-4, 0, 0], "v": [0, 3, 0], "material": "white"},
    {"type": "sphere", "center": [0.5, 0.5, -1], "radius": 0.5, "material": "white"}
  ],
  "lights": [{"type": "point", "position": [-0.5, 2.5, -0.5], "intensity": [3, 3, 3]}]
})";

// Per pixel and channel: the mean of `batches` independent images and its standard error.
struct MeanAndError {
    std::vector<double> mean, error;
};
template <typename Render>
MeanAndError batch_statistics(int batches, std::size_t values, Render&& render) {
    std::vector<double> sum(values, 0), sum2(values, 0);
    for (int b = 0; b < batches; ++b) {
        const Image image = render(std::uint64_t(100 + b));
        for (std::size_t i = 0; i < values; ++i) {
            const double v = double(image.pixels()[i / 3][int(i % 3)]);
            sum[i] += v;
            sum2[i] += v * v;
        }
    }
    MeanAndError out{std::vector<double>(values), std::vector<double>(values)};
    for (std::size_t i = 0; i < values; ++i) {
        const double m = sum[i] / batches;
        const double variance = std::max(0.0, (sum2[i] - batches * m * m) / (batches - 1));
        out.mean[i] = m;
        out.error[i] = std::sqrt(variance / batches);
    }
    return out;
}

// A light tracer for `s` that simulates `simulated`, with the material table it reads (importance).
struct ForwardTracer {
    MaterialTable materials;
    LightTracer tracer;
    ForwardTracer(const StudyScene& s, const EffectSet& simulated, LightTracerOptions options = {})
        : materials(s.scene, simulated, refraction_materials(Transport::kImportance)),
          tracer(s.prepared.world, materials, s.prepared.lights, s.camera, simulating(options, simulated)) {}
    static LightTracerOptions simulating(LightTracerOptions options, const EffectSet& simulated) {
        options.simulated = simulated;
        return options;
    }
};

// Chapter 08's default scene (its Cornell box and glass sphere) with the glass changed by `change`.
template <typename Change>
Scene default_scene_with_glass(Change&& change) {
    Scene scene = load_scene(scene_path("ch08_default.json"));
    for (Material& m : scene.materials)
        if (m.type == "dielectric") change(m);
    return scene;
}

// Two estimators' images, each the mean of independent batches (batch_statistics), agree pixel by pixel
// within error bars, and so do their means over the image.
void check_images_agree(const MeanAndError& a, const MeanAndError& b) {
    const std::size_t values = a.mean.size();
    int within3 = 0, beyond6 = 0;
    double sum_a = 0, sum_b = 0, variance_sum = 0;
    for (std::size_t i = 0; i < values; ++i) {
        const double d = a.mean[i] - b.mean[i];
        const double se = std::hypot(a.error[i], b.error[i]);
        const double z = se > 0 ? std::abs(d) / se : (d == 0 ? 0.0 : kInfinity);
        within3 += z < 3;
        beyond6 += z > 6;
        sum_a += a.mean[i];
        sum_b += b.mean[i];
        variance_sum += se * se;
    }
    INFO("values " << values << ", within 3 sigma " << within3 << ", beyond 6 sigma " << beyond6);
    CHECK(double(within3) / double(values) >= 0.97);
    CHECK(beyond6 == 0);
    // The image means: their difference against its standard error sqrt(Σ se²) / values.
    INFO("mean of a " << sum_a / double(values) << ", of b " << sum_b / double(values));
    CHECK(std::abs(sum_a - sum_b) <= 4 * std::sqrt(variance_sum));
    CHECK(sum_a > 0);
}

// Forward (connect) and reverse (chapter 06, MIS) images of `setup` agree pixel by pixel within error bars.
void check_forward_matches_reverse(const StudyScene& s, int spp) {
    constexpr int kBatches = 16;
    const std::size_t values = s.camera.width * std::size_t(s.camera.height) * 3;
    const ForwardTracer light_f(s, EffectSet::all());
    const LightTracer& light = light_f.tracer;
    const PathTracer path(s.prepared.world, s.prepared.materials, s.prepared.lights, PathOptions{});
    const auto forward = batch_statistics(kBatches, values, [&](std::uint64_t seed) {
        const RenderSettings settings = settings_of(s.camera.width, s.camera.height, spp / kBatches, seed);
        return render_light_tracing(light, settings, paths_per_image(settings)).render.image;
    });
    const auto reverse = batch_statistics(kBatches, values, [&](std::uint64_t seed) {
        return render_paths(path, s.camera,
                            settings_of(s.camera.width, s.camera.height, spp / kBatches, seed + 50))
            .image;
    });
    check_images_agree(forward, reverse);
}

}  // namespace

TEST_CASE("A scene point projects back to the film point its camera ray came through",
          "[ch08][ex:ch01.camera_ray][ex:ch08.project_direction]") {
    const PinholeCamera camera =
        make_pinhole_camera(CameraDesc{{1, 2, 3}, {-4, 5, 6}, {0, 1, 0}, 55}, 64, 48);
    for (Real px : {0.5f, 10.25f, 32.3f, 63.5f}) {
        for (Real py : {0.5f, 20.75f, 47.5f}) {
            const Ray ray = camera_ray(camera, px, py);
            const auto p = project_point(camera, ray.at(7.5f));
            REQUIRE(p);
            {
                INFO("the film point is not the one the camera ray came through: film_direction not inverted");
                CHECK(p->px == Approx(px).margin(1e-3));
                CHECK(p->py == Approx(py).margin(1e-3));
                CHECK(p->x == int(px));
                CHECK(p->y == int(py));
            }
            INFO("cos theta_c is not the cosine between the direction and the camera's axis");
            CHECK(p->cos_theta == Approx(glm::dot(ray.direction, camera.forward)).epsilon(1e-5));
        }
    }
    CHECK_FALSE(project_point(camera, camera.eye - camera.forward));  // behind the eye
    CHECK_FALSE(project_point(camera, camera.eye + camera.right * 100.0f + camera.forward));  // off the film
}

TEST_CASE("The pinhole importance integrates to 1 over a pixel: a pixel of radiance 1 reads 1",
          "[ch08][statistical][ex:ch08.pinhole_importance][ex:ch08.project_direction]") {
    // ∫ We cos θ_c dω over pixel j = 1: uniform directions on the sphere (pdf 1 / 4π), each in the pixel it
    // projects to; a 4×3 film with a 100° field of view, so corner pixels see large angles.
    const PinholeCamera camera = make_pinhole_camera(CameraDesc{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 100}, 4, 3);
    constexpr int kSamples = 2'000'000;
    std::vector<double> sums(12, 0);
    Pcg32 rng(7, 3);
    for (int i = 0; i < kSamples; ++i) {
        const Vec2 u = rng.next_vec2();
        const Real z = 1 - 2 * u.x, r = std::sqrt(std::max(Real(0), 1 - z * z)), phi = 2 * kPi * u.y;
        const Vec3 d(r * std::cos(phi), r * std::sin(phi), z);
        if (const auto p = project_direction(camera, d)) {
            sums[std::size_t(p->y * 4 + p->x)] +=
                double(pinhole_importance(camera, p->cos_theta) * p->cos_theta) * 4 * std::numbers::pi;
        }
    }
    for (std::size_t j = 0; j < sums.size(); ++j) {
        INFO("pixel " << j << ": the integral of We cos theta_c over the pixel is " << sums[j] / kSamples
                      << ", not 1: the importance is not normalised");
        CHECK(sums[j] / kSamples == Approx(1).epsilon(0.03));
    }
}

TEST_CASE("Lights are picked by power, and the light paths' starting throughput sums to the emitted power",
          "[ch08][statistical][ex:ch04.cosine_hemisphere][ex:ch06.uniform_sphere]") {
    const Scene scene = scene_from(R"({
      "camera": {"from": [0, 0, 5], "at": [0, 0, 0]},
      "materials": {"lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [2, 2, 2]}},
      "shapes": [{"type": "quad", "origin": [0, 0, 0], "u": [3, 0, 0], "v": [0, 1, 0], "material": "lamp"}],
      "lights": [{"type": "point", "position": [0, 4, 0], "intensity": [5, 5, 5]}]})");
    const EmitterSampler emitters(collect_lights(scene));
    const double quad_power = std::numbers::pi * 2 * 3, point_power = 4 * std::numbers::pi * 5;
    REQUIRE(emitters.light_count() == 2);
    CHECK(emitters.total_power() == Approx(quad_power + point_power).epsilon(1e-5));
    CHECK(emitters.probability(0) == Approx(quad_power / (quad_power + point_power)).epsilon(1e-5));
    Pcg32 rng(3, 1);
    double sum = 0;
    int from_point = 0;
    constexpr int kSamples = 200'000;
    for (int i = 0; i < kSamples; ++i) {
        const Real u_pick = rng.next_real();
        const Vec2 a = rng.next_vec2(), b = rng.next_vec2();
        const auto e = emitters.sample(u_pick, a, b);
        REQUIRE(e);
        sum += double(luminance(e->beta));
        from_point += e->delta_light;
        if (!e->delta_light) {
            CHECK(glm::dot(e->direction, e->origin.normal) >= 0);  // one-sided: into the front
            CHECK(e->origin.point.y >= 0);
            CHECK(e->origin.point.y <= 1);
        }
    }
    // Every sample's β₀ is the total power (β₀ = Φ_i / P_i), so the mean is exact up to rounding.
    CHECK(sum / kSamples == Approx(quad_power + point_power).epsilon(1e-4));
    CHECK(double(from_point) / kSamples == Approx(point_power / (quad_power + point_power)).epsilon(0.02));
}

TEST_CASE("Spot and distant lights start light paths whose throughput averages to their power",
          "[ch08][statistical][lights][ex:ch04.uniform_cone]") {
    // A spot of I = 3 with a 40-degree cone and a 10-degree band: Φ = 2π I (1 − (cos 30° + cos 40°) / 2); a
    // distant light of E = 2: Φ = π r² E, r = √3 the radius of the sphere around the unit sphere's box (β₀
    // exactly that in every path).
    const Scene scene = scene_from(R"({
      "camera": {"from": [0, 0, 5], "at": [0, 0, 0]},
      "materials": {"grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
      "shapes": [{"type": "sphere", "center": [1, 2, 3], "radius": 1, "material": "grey"}],
      "lights": [{"type": "spot", "position": [0, 4, 0], "at": [0, 0, 0], "intensity": [3, 3, 3],
                  "cone_angle": 40, "cone_delta": 10},
                 {"type": "distant", "direction": [0, 0, -2], "irradiance": [2, 2, 2]}]})");
    const double pi = std::numbers::pi, degree = pi / 180;
    const double spot_power = 2 * pi * 3 * (1 - (std::cos(30 * degree) + std::cos(40 * degree)) / 2);
    const double distant_power = pi * 3 * 2;
    const EmitterSampler emitters(collect_lights(scene));
    REQUIRE(emitters.light_count() == 2);
    CHECK(emitters.total_power() == Approx(spot_power + distant_power).epsilon(1e-5));
    Pcg32 rng(5, 1);
    double sum = 0;
    constexpr int kSamples = 200'000;
    for (int i = 0; i < kSamples; ++i) {
        const Real u_pick = rng.next_real();
        const Vec2 a = rng.next_vec2(), b = rng.next_vec2();
        const auto e = emitters.sample(u_pick, a, b);
        REQUIRE(e);
        REQUIRE(e->delta_light);
        sum += double(luminance(e->beta));
        if (e->origin.point.y > 3.9f) {  // the spot: from its point, within its cone about −y
            CHECK(e->direction.y <= -std::cos(40 * degree) + 1e-6);
        } else {  // the distant light: along −z, from the disk of radius r one radius before the centre
            CHECK(e->direction == Vec3(0, 0, -1));
            CHECK(double(e->origin.point.z) == Approx(3 + std::sqrt(3.0)).epsilon(1e-6));
            CHECK(glm::length(Vec2(e->origin.point.x - 1, e->origin.point.y - 2)) <= std::sqrt(3.0f) + 1e-5f);
        }
    }
    CHECK(sum / kSamples == Approx(spot_power + distant_power).epsilon(0.01));
}

TEST_CASE("Connecting light paths to the pinhole converges to chapter 06's image of the Cornell box",
          "[ch08][statistical][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch08.connect]"
          "[ex:ch08.pinhole_importance][ex:ch08.project_direction]") {
    const StudyScene s(load_scene(scene_path("ch06_default.json")), 16, 16);
    check_forward_matches_reverse(s, 1024);
}

TEST_CASE(
    "Connecting light paths to the pinhole converges to chapter 06's image of a room lit by a point light",
    "[ch08][statistical][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
    "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
    "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch05.termination][ex:ch06.path_tracer]"
    "[ex:ch06.uniform_sphere][ex:ch08.connect][ex:ch08.pinhole_importance]"
    "[ex:ch08.project_direction]") {
    const StudyScene s(scene_from(kPointLightRoom), 12, 12);
    check_forward_matches_reverse(s, 1024);
}

TEST_CASE("A glass sphere of index 1 changes nothing but hides what lies behind it from the light tracer",
          "[ch08][statistical][ex:ch01.camera_ray][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch05.termination][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]"
          "[ex:ch08.connect][ex:ch08.pinhole_importance][ex:ch08.project_direction]") {
    Scene with = default_scene_with_glass([](Material& m) { m.ior = 1; });
    Scene without = with;
    without.shapes.pop_back();  // the sphere is the last shape
    REQUIRE(std::holds_alternative<SphereShape>(with.shapes.back().geometry));
    const StudyScene a(with, 8, 8), b(without, 8, 8);
    const ForwardTracer ta_f(a, EffectSet::all());
    const LightTracer& ta = ta_f.tracer;
    const ForwardTracer tb_f(b, EffectSet::all());
    const LightTracer& tb = tb_f.tracer;
    // The pixels that see the sphere anywhere (a 6×6 grid of camera rays per pixel).
    std::vector<std::uint8_t> sphere(64, 0);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int k = 0; k < 36; ++k) {
                const auto hit = a.prepared.world.intersect(camera_ray(
                    a.camera, Real(x) + (Real(k % 6) + 0.5f) / 6, Real(y) + (Real(k / 6) + 0.5f) / 6));
                if (hit && a.scene.materials[std::size_t(hit->material)].type == "dielectric")
                    sphere[std::size_t(y * 8 + x)] = 1;
            }
    constexpr int kBatches = 8;
    const std::size_t values = 8 * 8 * 3;
    auto render = [](const LightTracer& t, std::uint64_t seed) {
        const RenderSettings settings = settings_of(8, 8, 512, seed);
        return render_light_tracing(t, settings, paths_per_image(settings)).render.image;
    };
    const auto ma = batch_statistics(kBatches, values, [&](std::uint64_t seed) { return render(ta, seed); });
    const auto mb =
        batch_statistics(kBatches, values, [&](std::uint64_t seed) { return render(tb, seed + 50); });
    double sum_a = 0, sum_b = 0, variance = 0, hidden_a = 0, hidden_b = 0;
    int seen = 0;
    for (std::size_t i = 0; i < values; ++i) {
        if (sphere[i / 3]) {
            hidden_a += ma.mean[i];
            hidden_b += mb.mean[i];
            continue;
        }
        ++seen;
        sum_a += ma.mean[i];
        sum_b += mb.mean[i];
        variance += ma.error[i] * ma.error[i] + mb.error[i] * mb.error[i];
    }
    REQUIRE(seen >= 100);
    // Light passes through unchanged: the pixels that do not see the sphere agree within error bars...
    CHECK(std::abs(sum_a - sum_b) <= 4 * std::sqrt(variance));
    // ...while a connection to the pinhole cannot pass through glass (a delta): the sphere's pixels lose
    // what lies behind it.
    CHECK(hidden_a < 0.8 * hidden_b);
}

// The exercises a render of the glass box by the combined tracer runs: the camera's path loop with chapter
// 07's glass, and the light tracer's connections.
#define kCombinedTracerExercises                                                                \
    "[ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"    \
    "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"   \
    "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]" \
    "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract][ex:ch08.connect]"      \
    "[ex:ch08.pinhole_importance][ex:ch08.project_direction]"

TEST_CASE(
    "Paths for all but the camera caustics, plus light paths for those, converge to chapter 06's "
    "image with less variance",
    "[ch08][statistical]" kCombinedTracerExercises) {
    const Scene scene = load_scene(scene_path("ch08_default.json"));
    const EffectSet all = needed(scene) & EffectSet::all();
    constexpr int kSide = 16, kBatches = 16, kSpp = 64;
    const std::size_t values = std::size_t(kSide * kSide * 3);
    const RenderScene prepared(scene, all, refraction_materials());
    const PinholeCamera camera = make_pinhole_camera(scene.camera, kSide, kSide);
    // Stratified points on both sides: the error bars of 16 batches assume near-normal batch means. Sobol
    // points take away most of the smooth noise and leave the caustic's skewed fireflies, whose error bars
    // 16 batches underestimate (measured over 6 sets of seeds: 96.8 % of the values within 3 sigma with
    // Sobol points, 98.3 % with stratified ones).
    CombinedOptions combined_options;
    combined_options.paths.sampler = PointSet::kStratified;
    PathOptions options = combined_options.paths;
    options.simulated = all;
    const PathTracer paths(prepared.world, prepared.materials, prepared.lights, options);
    const auto reverse = batch_statistics(kBatches, values, [&](std::uint64_t seed) {
        return render_paths(paths, camera, settings_of(kSide, kSide, kSpp, seed + 50)).image;
    });
    Image caustic(kSide, kSide);
    const auto combined = batch_statistics(kBatches, values, [&](std::uint64_t seed) {
        const CombinedResult r =
            render_combined(scene, all, settings_of(kSide, kSide, kSpp, seed), combined_options);
        for (std::size_t p = 0; p < caustic.pixels().size(); ++p)
            caustic.pixels()[p] += r.caustics.render.image.pixels()[p];
        return r.render.image;
    });
    // The sum is chapter 06's image: each path counted once, by one of the two.
    check_images_agree(combined, reverse);
    // The light paths carry a share of it (the caustic under the sphere): the split is not empty.
    CHECK(caustic.mean() / kBatches >
          0.01 * std::accumulate(reverse.mean.begin(), reverse.mean.end(), 0.0) / double(values));
    // And with less variance at equal samples: the squared standard errors summed over the image (0.65 times
    // the paths' at this size, where a pixel averages the fireflies of many; ch08_time_to_error measures the
    // gain on the full-size image).
    double v_reverse = 0, v_combined = 0;
    for (std::size_t i = 0; i < values; ++i) {
        v_reverse += reverse.error[i] * reverse.error[i];
        v_combined += combined.error[i] * combined.error[i];
    }
    INFO("summed variance: paths " << v_reverse << ", combined " << v_combined);
    CHECK(v_combined < 0.8 * v_reverse);
}

TEST_CASE("The combined tracer renders finite and the same bits on 1 and 3 threads",
          "[ch08]" kCombinedTracerExercises) {
    const Scene scene = load_scene(scene_path("ch08_default.json"));
    const EffectSet all = needed(scene) & EffectSet::all();
    const CombinedResult one = render_combined(scene, all, settings_of(24, 24, 4, 9, 1), {});
    const CombinedResult three = render_combined(scene, all, settings_of(24, 24, 4, 9, 3), {});
    CHECK(one.render.image.all_finite());
    CHECK(one.render.image.pixels() == three.render.image.pixels());
    CHECK(one.caustics.contributing_paths > 0);
    // Both tracers' rays are counted: the light paths' own (shadow-kind first rays) among them.
    CHECK(one.render.rays.total() == one.paths.rays.total() + one.caustics.render.rays.total());
}

TEST_CASE("An interrupted combined render equals the whole render of the samples it kept, caustics included",
          "[ch08][interrupt]" kCombinedTracerExercises) {
    // The caustic under the glass sphere is the light paths' share: a partial image without them was too dark.
    const Scene scene = load_scene(scene_path("ch08_default.json"));
    const EffectSet all = needed(scene) & EffectSet::all();
    // 512 light paths per camera sample of 16 × 16 pixels: 2^17, one wave of 8 chunks of 2^14 paths, so the
    // light paths of the samples kept are whole waves, as many as the whole render of those samples traces.
    CombinedOptions options;
    options.light_paths_per_sample = 512;
    options.paths.sampler = PointSet::kIndependent;  // a sample's numbers do not depend on the sample count
    int passes = 0;
    AfterEachPass stop_after_first([&](const PassReport&) {
        if (++passes == 1) set_interrupt_requested(true);  // as if Ctrl-C came at the end of the first pass
    });
    RenderSettings settings = settings_of(16, 16, 64, 7);
    settings.observer = &stop_after_first;
    const CombinedResult interrupted = render_combined(scene, all, settings, options);
    set_interrupt_requested(false);
    const CombinedResult whole = render_combined(scene, all, settings_of(16, 16, 1, 7), options);
    REQUIRE(whole.caustics.contributing_paths > 0);
    CHECK(interrupted.render.interrupted);
    CHECK(interrupted.render.samples_per_pixel == 1);
    CHECK(interrupted.caustics.render.samples == whole.caustics.render.samples);
    CHECK(interrupted.render.image.pixels() == whole.render.image.pixels());
}

TEST_CASE("Under an environment light the combined tracer is chapter 06's loop alone, bit for bit",
          "[ch08][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable][ex:ch03.robust_offset]"
          "[ex:ch05.termination][ex:ch06.path_tracer][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact]"
          "[ex:ch07.refract]") {
    // Light paths do not start at the environment, so no path may be left to them.
    const Scene scene = load_scene(scene_path("ch07_furnace_glass.json"));
    const EffectSet all = needed(scene) & EffectSet::all();
    const RenderSettings settings = settings_of(12, 12, 4, 5);
    const CombinedResult combined = render_combined(scene, all, settings, {});
    PathOptions options;
    options.simulated = all;
    const RenderScene prepared(scene, all, refraction_materials());
    const PathTracer paths(prepared.world, prepared.materials, prepared.lights, options);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, 12, 12);
    CHECK_FALSE(combined.split);
    CHECK(combined.caustics.render.samples == 0);
    CHECK(combined.render.image.pixels() == render_paths(paths, camera, settings).image.pixels());
}

TEST_CASE("Without glass or mirrors the path loop leaves out nothing and the caustic light paths add nothing",
          "[ch08][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    const StudyScene s(load_scene(scene_path("ch06_default.json")), 12, 12);
    const RenderSettings settings = settings_of(12, 12, 8, 3);
    const PathTracer all_paths(s.prepared.world, s.prepared.materials, s.prepared.lights, PathOptions{});
    // The same numbers drawn, the same light counted: the same image, bit for bit.
    CHECK(render_paths(all_paths, s.camera, settings).image.pixels() ==
          render_paths(all_paths, s.camera, settings, CameraCausticCut(3)).image.pixels());
    LightTracerOptions light_options;
    light_options.paths = LightPathSet::kCaustics;
    light_options.caustic_bounces = 3;
    const ForwardTracer caustics(s, EffectSet::all(), light_options);
    const SplatResult r = render_light_tracing(caustics.tracer, settings, paths_per_image(settings));
    CHECK(r.contributing_paths == 0);
    CHECK(r.render.image.mean() == 0);
    CHECK(r.render.rays.count[std::size_t(RayKind::kCamera)] == 0);  // no connection tried
}

TEST_CASE("A wall of radiance 1 reads 1 through the lens aperture and through the pinhole connection",
          "[ch08][statistical][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch08.pinhole_importance][ex:ch08.project_direction]") {
    // A lamp of radiance 1, larger than the view (half-height 10 tan 20° = 3.6), 10 units in front of the
    // camera: every pixel is 1.
    const StudyScene s(scene_from(R"({
      "camera": {"from": [0, 0, 10], "at": [0, 0, 0], "vfov": 40},
      "materials": {"lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [1, 1, 1]}},
      "shapes": [{"type": "quad", "origin": [-5, -5, 0], "u": [10, 0, 0], "v": [0, 10, 0],
                  "material": "lamp"}]})"),
                       4, 4);
    LightTracerOptions options = ForwardTracer::simulating({}, EffectSet::all());
    const ForwardTracer pinhole_f(s, options.simulated, options);
    const LightTracer& pinhole = pinhole_f.tracer;
    const SplatResult connect = render_light_tracing(pinhole, settings_of(4, 4, 16384, 1), 4 * 4 * 16384);
    options.variant = CameraVariant::kAperture;
    options.aperture_radius = 0.5f;
    const ForwardTracer lens_f(s, options.simulated, options);
    const LightTracer& lens = lens_f.tracer;
    const SplatResult aperture = render_light_tracing(lens, settings_of(4, 4, 1, 1), 4'000'000);
    for (const Color& c : connect.render.image.pixels()) CHECK(c.g == Approx(1).epsilon(0.03));
    CHECK(connect.render.image.mean() == Approx(1).epsilon(0.01));
    CHECK(aperture.render.image.mean() == Approx(1).epsilon(0.03));
    // Almost no path finds the lens: a fraction of about (π R² / d²) cos / π of the lamp's paths.
    const double fraction = double(aperture.contributing_paths) / 4'000'000.0;
    INFO("fraction through the lens " << fraction);
    CHECK(fraction > 0);
    CHECK(fraction < 0.01);
    CHECK(aperture.render.rays[RayKind::kCamera] == 0);  // the lens is found by chance, not by a ray to it
}

TEST_CASE("A light path that never reaches the camera contributes nothing",
          "[ch08][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch05.termination][ex:ch08.connect]"
          "[ex:ch08.project_direction]") {
    SECTION("the light faces away from everything") {
        const StudyScene s(scene_from(R"({
          "camera": {"from": [0, 0, 5], "at": [0, 0, 0]},
          "materials": {"lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [4, 4, 4]},
                        "white": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]}},
          "shapes": [{"type": "quad", "origin": [-1, -1, 0], "u": [0, 2, 0], "v": [2, 0, 0], "material": "lamp"},
                     {"type": "quad", "origin": [-3, -3, 1], "u": [6, 0, 0], "v": [0, 6, 0], "material": "white"}]})"),
                           8, 8);
        // The lamp emits toward −z (u × v = −z); the white quad lies on its dark side.
        const ForwardTracer tracer_f(s, EffectSet::all());
        const LightTracer& tracer = tracer_f.tracer;
        const SplatResult r = render_light_tracing(tracer, settings_of(8, 8, 16, 1), 1024);
        CHECK(r.contributing_paths == 0);
        CHECK(r.render.image.mean() == 0);
        CHECK(r.render.rays[RayKind::kShadow] == 1024);  // every path left its light...
        CHECK(r.render.rays[RayKind::kCamera] == 0);     // ...and no vertex could be joined to the camera
    }
    SECTION("a wall hides every lit surface from the camera") {
        const StudyScene s(scene_from(R"({
          "camera": {"from": [0, 1, 5], "at": [0, 1, 0]},
          "materials": {"lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [4, 4, 4]},
                        "white": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]}},
          "shapes": [{"type": "quad", "origin": [-2, 3, -3], "u": [4, 0, 0], "v": [0, 0, 2], "material": "lamp"},
                     {"type": "quad", "origin": [-5, 0, 0], "u": [0, 0, -5], "v": [10, 0, 0], "material": "white"},
                     {"type": "quad", "origin": [-50, -50, 2], "u": [100, 0, 0], "v": [0, 100, 0], "material": "white"}]})"),
                           8, 8);
        const ForwardTracer tracer_f(s, EffectSet::all());
        const LightTracer& tracer = tracer_f.tracer;
        const SplatResult r = render_light_tracing(tracer, settings_of(8, 8, 16, 1), 4096);
        CHECK(r.contributing_paths == 0);
        CHECK(r.render.image.mean() == 0);
        CHECK(r.render.rays[RayKind::kCamera] > 0);  // connections were tried: the wall stopped them all
        CHECK(r.render.rays[RayKind::kIndirect] > 0);
    }
}

TEST_CASE("Light tracing counts its rays by kind and traces only the effects the scene calls for",
          "[ch08][ex:ch02.quad_packet][ex:ch02.sphere_stable][ex:ch03.robust_offset]"
          "[ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.mirror]"
          "[ex:ch05.termination][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]"
          "[ex:ch08.connect][ex:ch08.pinhole_importance][ex:ch08.project_direction]") {
    const Scene cornell = load_scene(scene_path("ch06_default.json"));
    SECTION("every path leaves its light once: one shadow-kind ray per path; no mirror, no reflection rays") {
        const StudyScene s(cornell, 8, 8);
        const ForwardTracer tracer_f(s, needed(s.scene));
        const LightTracer& tracer = tracer_f.tracer;
        const SplatResult r = render_light_tracing(tracer, settings_of(8, 8, 16, 1), 5000);
        CHECK(r.render.samples == 5000);
        CHECK(r.render.rays[RayKind::kShadow] == 5000);
        CHECK(r.render.rays[RayKind::kReflection] == 0);
        CHECK(r.render.rays[RayKind::kRefraction] == 0);
        CHECK(r.render.rays[RayKind::kIndirect] > 0);
        // At most one connection per vertex: the light's point, then one per bounce.
        CHECK(r.render.rays[RayKind::kCamera] <= 5000 + 5000 + r.render.rays[RayKind::kIndirect]);
    }
    SECTION("a scene without lights traces nothing") {
        Scene dark = cornell;
        for (Material& m : dark.materials) m.emission = Color(0);
        const StudyScene s(dark, 8, 8);
        const ForwardTracer tracer_f(s, needed(s.scene));
        const LightTracer& tracer = tracer_f.tracer;
        const SplatResult r = render_light_tracing(tracer, settings_of(8, 8, 16, 1), 1000);
        CHECK(r.render.rays.total() == 0);
        CHECK(r.render.image.mean() == 0);
    }
    SECTION("a scene that calls only for direct light: depth 1, no indirect rays") {
        Scene direct = cornell;
        direct.effects = EffectSet{Effect::kCameraRays, Effect::kShadows, Effect::kDirect};
        const StudyScene s(direct, 8, 8);
        const LightTracerOptions options = ForwardTracer::simulating({}, needed(s.scene));
        CHECK_FALSE(options.simulates(Effect::kIndirect));
        const ForwardTracer tracer_f(s, options.simulated, options);
        const LightTracer& tracer = tracer_f.tracer;
        const SplatResult r = render_light_tracing(tracer, settings_of(8, 8, 16, 1), 5000);
        CHECK(r.render.rays[RayKind::kIndirect] == 0);
        CHECK(r.render.rays[RayKind::kReflection] == 0);
        CHECK(r.render.rays[RayKind::kShadow] == 5000);
        CHECK(r.render.rays[RayKind::kCamera] <= 2 * 5000);  // the light's point and the first hit
        CHECK(r.render.rays[RayKind::kCamera] > 5000);
    }
    SECTION("the mirror scene bounces off its mirror: reflection rays, no refraction rays") {
        const StudyScene s(load_scene(scene_path("ch08_mirror.json")), 8, 8);
        const ForwardTracer tracer_f(s, needed(s.scene));
        const LightTracer& tracer = tracer_f.tracer;
        const SplatResult r = render_light_tracing(tracer, settings_of(8, 8, 16, 1), 20000);
        CHECK(r.render.rays[RayKind::kReflection] > 0);
        CHECK(r.render.rays[RayKind::kRefraction] == 0);
    }
    SECTION("the glass sphere refracts: refraction rays; without the refraction effect, none") {
        const StudyScene s(load_scene(scene_path("ch08_default.json")), 8, 8);
        const ForwardTracer glass_f(s, needed(s.scene));
        const LightTracer& glass = glass_f.tracer;
        const SplatResult r = render_light_tracing(glass, settings_of(8, 8, 16, 1), 20000);
        CHECK(r.render.rays[RayKind::kRefraction] > 0);
        CHECK(r.render.rays[RayKind::kReflection] > 0);  // Fresnel reflection off the glass
        const ForwardTracer lambert_f(s, needed(s.scene).without(EffectSet{Effect::kRefraction}));
        const LightTracer& lambert = lambert_f.tracer;
        const SplatResult l = render_light_tracing(lambert, settings_of(8, 8, 16, 1), 20000);
        CHECK(l.render.rays[RayKind::kRefraction] == 0);
        CHECK(l.render.rays[RayKind::kReflection] == 0);
    }
}

TEST_CASE("The default scene renders finite, plausible and identical for 1, 2 and 3 threads",
          "[ch08][ex:ch02.quad_packet][ex:ch02.sphere_stable][ex:ch03.robust_offset]"
          "[ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch05.termination]"
          "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract][ex:ch08.connect]"
          "[ex:ch08.pinhole_importance][ex:ch08.project_direction]") {
    const StudyScene s(load_scene(scene_path("ch08_default.json")), 24, 24);
    const ForwardTracer tracer_f(s, needed(s.scene));
    const LightTracer& tracer = tracer_f.tracer;
    // 24 × 24 × 96 paths: several chunks, so threads really share the work.
    const std::uint64_t paths = 24 * 24 * 96;
    REQUIRE(paths > 2 * chunk_size(24, 24));
    const SplatResult one = render_light_tracing(tracer, settings_of(24, 24, 96, 1, 1), paths);
    const SplatResult two = render_light_tracing(tracer, settings_of(24, 24, 96, 1, 2), paths);
    const SplatResult three = render_light_tracing(tracer, settings_of(24, 24, 96, 1, 3), paths);
    CHECK(one.render.image.all_finite());
    CHECK(one.render.image.mean() > 0.05);
    CHECK(one.render.image.mean() < 0.5);
    CHECK(one.render.image.pixels() == two.render.image.pixels());
    CHECK(one.render.image.pixels() == three.render.image.pixels());
    CHECK(one.render.rays.count == two.render.rays.count);
    CHECK(one.contributing_paths == three.contributing_paths);
    const SplatResult other_seed = render_light_tracing(tracer, settings_of(24, 24, 96, 2, 2), paths);
    CHECK(other_seed.render.image.pixels() != one.render.image.pixels());
}

TEST_CASE("Time to an RMSE is read off a log-log curve, and extrapolated with RMSE proportional to t^-1/2",
          "[ch08]") {
    const std::vector<double> seconds{1, 4, 16}, rmse{0.4, 0.2, 0.1};
    CHECK(time_to_rmse(seconds, rmse, 0.2) == Approx(4));
    CHECK(time_to_rmse(seconds, rmse, 0.4 / std::sqrt(2.0)) == Approx(2));
    CHECK(time_to_rmse(seconds, rmse, 0.05) == Approx(64));
    CHECK(time_to_rmse(seconds, rmse, 0.8) == Approx(0.25));
    const Image a(2, 1), b(2, 1);
    Image c = a;
    c.at(1, 0) = Color(3);
    CHECK(masked_rmse(c, b, {1, 0}) == 0);
    CHECK(masked_rmse(c, b, {0, 1}) == Approx(3));
}

TEST_CASE("Connections at the eye, edge-on and at the film's edge add nothing and never NaN",
          "[ch08][stability][ex:ch08.connect][ex:ch08.pinhole_importance][ex:ch08.project_direction]") {
    const StudyScene s(load_scene(scene_path("ch06_default.json")), 8, 8);
    const ForwardTracer tracer_f(s, EffectSet::all());
    const LightTracer& tracer = tracer_f.tracer;
    Image film(8, 8);
    RayCounts rays;
    const LambertBrdf lambert{Color(0.5f)};
    Hit at_eye;
    at_eye.point = s.camera.eye;  // r = 0: no direction to the eye
    at_eye.normal = -s.camera.forward;
    CHECK_FALSE(tracer.connect(at_eye, at_eye.normal, lambert, Color(1), film, rays));
    Hit edge_on;  // the eye lies in the surface's plane: cos θ_x = 0
    edge_on.point = s.camera.eye + 500.0f * s.camera.forward;
    edge_on.normal = s.camera.right;
    CHECK_FALSE(tracer.connect(edge_on, edge_on.normal, lambert, Color(1), film, rays));
    CHECK(rays.total() == 0);  // neither needed a visibility ray
    CHECK(film.mean() == 0);
    CHECK(film.all_finite());
    // The film's edges: a direction exactly on the right or bottom edge is outside (px = W), one just inside
    // lands in the last pixel, and the zero direction nowhere.
    const PinholeCamera& c = s.camera;
    CHECK_FALSE(project_direction(c, c.forward + c.half_width * c.right));
    CHECK_FALSE(project_direction(c, c.forward - c.half_height * c.up));
    const auto inside = project_direction(c, c.forward + 0.99999f * c.half_width * c.right);
    REQUIRE(inside);
    CHECK(inside->x == 7);
    CHECK_FALSE(project_direction(c, Vec3(0)));
    CHECK(std::isfinite(pinhole_importance(c, 1e-3f)));
}

TEST_CASE("A connection's splat falls with the square of the distance and follows the cosine at the vertex",
          "[ch08][ex:ch02.quad_packet][ex:ch02.sphere_stable][ex:ch08.connect][ex:ch08.pinhole_importance]"
          "[ex:ch08.project_direction]") {
    // Vertices on the camera's axis, in front of the box, facing the eye or tilted by 60 degrees: whatever
    // form the geometry term takes, the splat of the same vertex at twice the distance is 4 times smaller, and
    // tilted it is cos 60 = 1/2 of facing (a Lambert surface's f is the same both ways).
    const StudyScene s(load_scene(scene_path("ch06_default.json")), 8, 8);
    const ForwardTracer tracer_f(s, EffectSet::all());
    const LambertBrdf lambert{Color(0.5f)};
    const auto splat_of = [&](Real distance, Real tilt) {
        Image film(8, 8);
        RayCounts rays;
        Hit hit;
        hit.point = s.camera.eye + distance * s.camera.forward;
        hit.normal = std::cos(tilt) * -s.camera.forward + std::sin(tilt) * s.camera.right;
        tracer_f.tracer.connect(hit, hit.normal, lambert, Color(1), film, rays);
        return film.mean();
    };
    const double near = splat_of(100, 0), far = splat_of(200, 0), tilted = splat_of(100, Real(kPi / 3));
    REQUIRE(near > 0);
    {
        INFO("twice as far, the splat is " << near / far << " times smaller, not 4: the square of the distance");
        CHECK(near / far == Approx(4).epsilon(1e-4));
    }
    INFO("tilted by 60 degrees, the splat is " << tilted / near << " of facing, not 1/2: the cosine at the vertex");
    CHECK(tilted / near == Approx(0.5).epsilon(1e-4));
}

// ---------------------------------------------------------------------------------------------------------
// Emission sampling against its pdfs (the shared chi-square harness), and rough glass seen by light paths

namespace {

using namespace rt::test;

// Every chi-square test of this file: the emitted direction of 4 kinds of light, the choice among lights 1.
const double kAlphaPerTest = sidak_level(5);

// The one light of a scene holding only `shapes` (an emissive one) or `lights` (a point light), as an
// EmitterSampler.
EmitterSampler one_light(const std::string& shapes, const std::string& lights) {
    const std::string lamp =
        shapes.empty() ? "" : R"("lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [2, 2, 2]})";
    const Scene scene = scene_from(R"({"camera": {"from": [0, 0, 5], "at": [0, 0, 0]}, "materials": {)" +
                                   lamp + R"(}, "shapes": [)" + shapes + R"(], "lights": [)" + lights + "]}");
    return EmitterSampler(collect_lights(scene));
}

// The direction a light path leaves along, u_direction from the harness and u_point from its own generator;
// `local`: in the frame of the point's normal (a sphere's normal changes from point to point).
DirectionSampler emitted_directions(const EmitterSampler& emitters, bool local, std::uint64_t seed) {
    auto points = std::make_shared<Pcg32>(seed, 29);
    return [&emitters, local, points](Vec2 u) {
        const auto e = emitters.sample(Real(0.5), points->next_vec2(), u);
        if (!e) return Drawn{Vec3(0), 0.0};
        const Vec3 w = local ? make_frame(e->origin.normal).to_local(e->direction) : e->direction;
        return Drawn{w, 0.0};
    };
}

// A planar light of normal n emits cosine-weighted world directions about n: pdf max(0, w · n) / π.
void require_cosine_about(const EmitterSampler& emitters, const Vec3& n, std::uint64_t seed) {
    require_fit(
        test_directions(
            emitted_directions(emitters, false, seed),
            [&](const Vec3& w) { return std::max(0.0, double(glm::dot(w, n))) / std::numbers::pi; }, seed),
        kAlphaPerTest);
}

}  // namespace

TEST_CASE(
    "Emitted directions fit their pdfs by chi-square: cosine about the normal for a quad, a triangle "
    "and a sphere light, uniform over the sphere for a point light",
    "[ch08][statistical][ex:ch04.cosine_hemisphere][ex:ch04.uniform_triangle][ex:ch06.uniform_sphere]") {
    SECTION("a tilted quad: cos θ / π about its normal, in world directions") {
        const EmitterSampler quad = one_light(
            R"({"type": "quad", "origin": [0, 0, 0], "u": [2, 0, 1], "v": [0, 1, 0.5], "material": "lamp"})",
            "");
        require_cosine_about(quad, glm::normalize(glm::cross(Vec3(2, 0, 1), Vec3(0, 1, 0.5f))), 1);
    }
    SECTION("a triangle: cos θ / π about its normal") {
        const EmitterSampler triangle = one_light(
            R"({"type": "triangle", "vertices": [[0, 0, 0], [1, 0, -1], [0, 1, 0]], "material": "lamp"})",
            "");
        require_cosine_about(triangle, glm::normalize(glm::cross(Vec3(1, 0, -1), Vec3(0, 1, 0))), 2);
    }
    SECTION("a sphere: cos θ / π about the normal at the point it starts from") {
        const EmitterSampler sphere =
            one_light(R"({"type": "sphere", "center": [1, 2, 3], "radius": 0.5, "material": "lamp"})", "");
        require_fit(test_directions(
                        emitted_directions(sphere, true, 3),
                        [](const Vec3& w) { return double(cosine_hemisphere_pdf(w.z)); }, 3),
                    kAlphaPerTest);
    }
    SECTION("a point light: 1 / (4 pi) over the sphere") {
        const EmitterSampler point =
            one_light("", R"({"type": "point", "position": [0, 1, 0], "intensity": [3, 3, 3]})");
        require_fit(test_directions(
                        emitted_directions(point, false, 4),
                        [](const Vec3&) { return double(kUniformSpherePdf); }, 4),
                    kAlphaPerTest);
    }
}

TEST_CASE(
    "A two-sided quad light starts light paths from both sides: cos θ / (2 pi) about either normal, "
    "twice the power",
    "[ch08][statistical][ex:ch04.cosine_hemisphere]") {
    const Scene scene = scene_from(R"({"camera": {"from": [0, 0, 5], "at": [0, 0, 0]},
      "materials": {"lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [2, 2, 2], "two_sided": true}},
      "shapes": [{"type": "quad", "origin": [0, 0, 0], "u": [3, 0, 0], "v": [0, 1, 0], "material": "lamp"}]})");
    const EmitterSampler emitters(collect_lights(scene));
    const double power = 2 * std::numbers::pi * 2 * 3;  // two sides of π L A
    CHECK(emitters.total_power() == Approx(power).epsilon(1e-5));
    require_fit(test_directions(
                    emitted_directions(emitters, false, 5),
                    [](const Vec3& w) { return std::abs(double(w.z)) / (2 * std::numbers::pi); }, 5),
                kAlphaPerTest);
    Pcg32 rng(3, 1);
    double sum = 0;
    constexpr int kSamples = 10'000;
    for (int i = 0; i < kSamples; ++i) {
        const Real u_pick = rng.next_real();
        const Vec2 a = rng.next_vec2(), b = rng.next_vec2();
        const auto e = emitters.sample(u_pick, a, b);
        REQUIRE(e);
        CHECK(glm::dot(e->direction, e->origin.normal) >= 0);  // into the side it starts from
        sum += double(luminance(e->beta));
    }
    CHECK(sum / kSamples == Approx(power).epsilon(1e-4));  // every β₀ is Φ / P
}

TEST_CASE(
    "Light paths start on each light with probability proportional to its power, by chi-square over "
    "the lights",
    "[ch08][statistical][ex:ch04.cosine_hemisphere][ex:ch06.uniform_sphere]") {
    // Powers Φ = π lum(Le) A (one-sided area lights) and 4π lum(I) (a point light), computed here from the
    // scene: a dim large quad, a bright small quad, a sphere and a point light, told apart by where they
    // start.
    const Scene scene = scene_from(R"({"camera": {"from": [0, 0, 5], "at": [0, 0, 0]},
      "materials": {"dim": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [1, 1, 1]},
                    "bright": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [6, 3, 1]}},
      "shapes": [{"type": "quad", "origin": [0, 0, 0], "u": [3, 0, 0], "v": [0, 2, 0], "material": "dim"},
                 {"type": "quad", "origin": [10, 0, 0], "u": [1, 0, 0], "v": [0, 0.5, 0], "material": "bright"},
                 {"type": "sphere", "center": [20, 0, 0], "radius": 0.4, "material": "bright"}],
      "lights": [{"type": "point", "position": [30, 0, 0], "intensity": [2, 2, 2]}]})");
    const EmitterSampler emitters(collect_lights(scene));
    REQUIRE(emitters.light_count() == 4);
    const double bright = double(luminance(Color(6, 3, 1))), pi = std::numbers::pi;
    const std::vector<double> power{pi * 1 * 6, pi * bright * 0.5, pi * bright * 4 * pi * 0.4 * 0.4,
                                    4 * pi * 2};
    const double total = power[0] + power[1] + power[2] + power[3];
    constexpr int kDraws = 400000;
    std::vector<double> observed(4, 0), expected(4, 0);
    for (std::size_t i = 0; i < 4; ++i) expected[i] = kDraws * power[i] / total;
    Pcg32 rng(31, 1);
    for (int k = 0; k < kDraws; ++k) {
        const Real u_pick = rng.next_real();
        const Vec2 a = rng.next_vec2(), b = rng.next_vec2();
        const auto e = emitters.sample(u_pick, a, b);
        REQUIRE(e);
        // The lights stand 10 apart along x: which one a path starts on is where it starts.
        observed[std::size_t(std::clamp(int(std::lround(e->origin.point.x / 10)), 0, 3))] += 1;
    }
    const ChiSquare r = chi_square(observed, expected);
    INFO("observed " << observed[0] << ", " << observed[1] << ", " << observed[2] << ", " << observed[3]
                     << "; chi-square " << r.statistic << ", " << r.dof << " dof, p = " << r.p_value);
    CHECK(r.dof == 3);
    CHECK(r.p_value > kAlphaPerTest);
}

TEST_CASE(
    "Light paths through rough glass converge to chapter 06's image: forward and reverse agree within "
    "error bars",
    "[ch08][statistical][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
    "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
    "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
    "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch07.fresnel_exact]"
    "[ex:ch07.refract][ex:ch08.connect][ex:ch08.pinhole_importance][ex:ch08.project_direction]") {
    // Chapter 08's Cornell box with its sphere frosted (roughness 0.3): not a delta, so light paths connect
    // to the pinhole through it, carrying importance (Transport::kImportance), and both renders must agree.
    const StudyScene s(default_scene_with_glass([](Material& m) { m.roughness = 0.3f; }), 10, 10);
    const auto& materials = s.scene.materials;
    const int glass =
        int(std::find_if(materials.begin(), materials.end(),
                         [](const Material& m) { return m.type == "dielectric"; }) -
            materials.begin());
    REQUIRE(glass < int(materials.size()));
    CHECK(s.importance.bsdf(glass).flags().transmission);
    CHECK_FALSE(s.importance.bsdf(glass).flags().delta);
    check_forward_matches_reverse(s, 1024);
}

TEST_CASE("The light tracer reports its image after each wave of paths, and the last report is its image",
          "[splat][live]") {
    // Path i adds 1 to pixel i mod 32 of an 8 × 4 image: after N paths (a multiple of 32) every pixel reads
    // (N / 32) / N = 1/32 exactly. 20 chunks of 2^14 paths make waves of 8, 8 and 4 chunks.
    RenderSettings settings{8, 4, 1, 3, 2, ProgressStyle::kNone};
    const std::uint64_t pixels = 32, chunk = chunk_size(8, 4);
    REQUIRE(chunk == (1u << 14));
    auto trace = [&](std::uint64_t i, Pcg32&, Image& film, RayCounts& rays) {
        film.pixels()[std::size_t(i % pixels)] += Color(1);
        rays.add(RayKind::kCamera, 1);
        return true;
    };
    std::vector<std::uint64_t> samples;
    std::vector<std::uint32_t> fewest;
    Image last;
    AfterEachPass watch([&](const PassReport& pass) {
        samples.push_back(pass.samples);
        fewest.push_back(pass.fewest_samples);
        CHECK(pass.samples_held == pass.samples);
        CHECK(pass.rays[RayKind::kCamera] == pass.samples);
        last = pass.image;
    });
    settings.observer = &watch;
    const SplatResult r = render_light_paths(settings, 20 * chunk, trace);
    CHECK(samples == std::vector<std::uint64_t>{8 * chunk, 16 * chunk, 20 * chunk});
    const auto per_pixel = [&](std::uint64_t paths) { return std::uint32_t(paths / pixels); };
    CHECK(fewest ==
          std::vector<std::uint32_t>{per_pixel(8 * chunk), per_pixel(16 * chunk), per_pixel(20 * chunk)});
    REQUIRE(last.pixel_count() == r.render.image.pixel_count());
    for (std::size_t i = 0; i < last.pixel_count(); ++i) {
        REQUIRE(last.pixels()[i] == r.render.image.pixels()[i]);
        REQUIRE(last.pixels()[i] == Color(Real(1) / 32));
    }
}
