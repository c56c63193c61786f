// Chapter 07: BSDF refraction. Snell's law and the exact Fresnel reflectance at their hard cases for η = 1.5
// against double-precision references ([stability]): normal incidence, Brewster's angle, the critical angle
// from inside, total internal reflection, grazing incidence, reciprocity, η = 1, the refracted direction
// (unit, in the plane of incidence, Snell, reversible), flipping the normal, R + T = 1, no NaN. The sampled
// dielectric ([statistical]), Beer–Lambert, the furnace (a glass sphere and an η = 1 sphere under a uniform
// environment render 1 within error bars), ray counts for the effects a scene calls for, and the default
// scene. The depth study's CSV.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <iterator>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "04_direct_lighting/brdf.hpp"
#include "04_direct_lighting/light_set.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "07_bsdf_refraction/benchmark/path_parts.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "07_bsdf_refraction/coated_diffuse.hpp"
#include "07_bsdf_refraction/conductor.hpp"
#include "07_bsdf_refraction/depth_study.hpp"
#include "07_bsdf_refraction/dielectric.hpp"
#include "07_bsdf_refraction/fresnel.hpp"
#include "07_bsdf_refraction/refraction_materials.hpp"
#include "07_bsdf_refraction/rough_dielectric.hpp"
#include "07_bsdf_refraction/snell.hpp"
#include "random_unit.hpp"
#include "rt/core/conductor_presets.hpp"
#include "rt/core/errors.hpp"
#include "rt/core/random.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/material_kind.hpp"
#include "rt/io/scene_loader.hpp"
#include "support/chi_square.hpp"

using namespace rt;

namespace {

constexpr double kEta = 1.5;
const Vec3 kUp{0, 0, 1};

double deg(double degrees) {
    return degrees * std::numbers::pi / 180;
}

// wo at angle θ from the normal +z, in the x–z plane.
Vec3 direction_at(double theta) {
    return {Real(std::sin(theta)), 0, Real(std::cos(theta))};
}

// The transmittance of an interface from the transmission amplitudes, independently of R:
// t_perp = 2 cos_i / (cos_i + η cos_t), t_par = 2 cos_i / (η cos_i + cos_t), T = η cos_t / cos_i (t²) / 2.
double transmittance(double cos_i, double eta) {
    const double sin2_t = (1 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1) return 0;
    const double cos_t = std::sqrt(1 - sin2_t);
    const double t_perp = 2 * cos_i / (cos_i + eta * cos_t);
    const double t_par = 2 * cos_i / (eta * cos_i + cos_t);
    return eta * cos_t / cos_i * (t_perp * t_perp + t_par * t_par) / 2;
}

Scene scene_from(const std::string& json) {
    return parse_scene(json, "test.json");
}

RenderSettings small_settings(int size, int spp) {
    RenderSettings s;
    s.width = s.height = size;
    s.samples_per_pixel = spp;
    s.seed = 7;
    s.threads = 2;
    s.progress = ProgressStyle::kNone;
    return s;
}

// What a run of chapter 07 simulates for `scene`: what run_chapter() computes, needed ∩ supported.
EffectSet chapter07_effects(const Scene& scene) {
    return simulated_effects(scene, kRefractionChapterEffects);
}

RenderResult render_scene(const Scene& scene, const RenderSettings& settings, Renderer* used = nullptr) {
    const EffectSet simulated = chapter07_effects(scene);
    const Renderer renderer = choose_renderer(simulated);
    if (used) *used = renderer;
    return render_with(renderer, scene, simulated, settings, {});
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Fresnel and Snell at the hard cases

TEST_CASE("Normal incidence reflects R = ((eta - 1) / (eta + 1))^2 = 0.04 from either side",
          "[stability][ex:ch07.fresnel_exact][ex:ch07.fresnel_schlick][ex:ch07.refract]") {
    CHECK(fresnel_dielectric(1, Real(kEta)) == Approx(0.04).margin(1e-7));
    CHECK(fresnel_dielectric(1, Real(1 / kEta)) == Approx(0.04).margin(1e-7));
    CHECK(fresnel_schlick(1, Real(kEta)) == Approx(0.04).margin(1e-7));
    const auto wt = refract(kUp, kUp, Real(kEta));
    REQUIRE(wt);
    CHECK(wt->z == Approx(-1).margin(1e-7));
}

TEST_CASE("At Brewster's angle 56.3099 degrees only the perpendicular part reflects: R = 0.0739645",
          "[stability][ex:ch07.fresnel_exact]") {
    const double brewster = std::atan(kEta);
    CHECK(brewster * 180 / std::numbers::pi == Approx(56.3099).margin(1e-4));
    CHECK(fresnel_dielectric(Real(std::cos(brewster)), Real(kEta)) == Approx(0.0739645).margin(2e-7));
}

TEST_CASE(
    "From inside: the critical angle is 41.8103 degrees, below it refraction succeeds, R(41) = 0.379751",
    "[stability][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    const double critical = std::asin(1 / kEta);
    CHECK(critical * 180 / std::numbers::pi == Approx(41.8103).margin(1e-4));
    const Real eta = Real(1 / kEta);
    CHECK(fresnel_dielectric(Real(std::cos(deg(41))), eta) == Approx(0.379751).margin(2e-6));
    const auto wt = refract(direction_at(deg(41)), kUp, eta);
    REQUIRE(wt);
    // sin θ_t = 1.5 sin 41°.
    CHECK(double(std::hypot(wt->x, wt->y)) == Approx(kEta * std::sin(deg(41))).margin(1e-5));
}

TEST_CASE(
    "At 42 degrees and exactly at the critical angle from inside: total internal reflection, R = 1, no NaN",
    "[stability][ex:ch07.fresnel_exact][ex:ch07.fresnel_schlick][ex:ch07.refract]") {
    const Real eta = Real(1 / kEta);
    for (double theta : {deg(42), std::asin(1 / kEta), deg(60), deg(89.9)}) {
        INFO("theta " << theta * 180 / std::numbers::pi);
        const Real cos_i = Real(std::cos(theta));
        CHECK(fresnel_dielectric(cos_i, eta) == 1);
        CHECK(fresnel_schlick(cos_i, eta) == 1);
        CHECK_FALSE(refract(direction_at(theta), kUp, eta).has_value());
    }
    // Just below the critical angle, within a float's reach, refraction still succeeds and R < 1.
    const Real below = Real(std::cos(std::asin(1 / kEta) - 1e-3));
    CHECK(fresnel_dielectric(below, eta) < 1);
    CHECK(refract(direction_at(std::asin(1 / kEta) - 1e-3), kUp, eta).has_value());
}

TEST_CASE("Grazing incidence reflects everything, from either side",
          "[stability][ex:ch07.fresnel_exact][ex:ch07.fresnel_schlick]") {
    for (Real eta : {Real(kEta), Real(1 / kEta)}) {
        CHECK(fresnel_dielectric(0, eta) == 1);
        CHECK(fresnel_schlick(0, eta) == 1);
        CHECK(fresnel_dielectric(Real(1e-4), eta) > Real(0.99));
        CHECK(std::isfinite(fresnel_dielectric(Real(-0.0), eta)));
    }
}

TEST_CASE("Reciprocity: R(30 degrees, 1.5) = R(theta_t, 1 / 1.5)", "[stability][ex:ch07.fresnel_exact]") {
    const double theta_t = std::asin(std::sin(deg(30)) / kEta);
    const Real outside = fresnel_dielectric(Real(std::cos(deg(30))), Real(kEta));
    const Real inside = fresnel_dielectric(Real(std::cos(theta_t)), Real(1 / kEta));
    CHECK(outside == Approx(0.0415226).margin(1e-6));
    CHECK(inside == Approx(double(outside)).margin(1e-6));
}

TEST_CASE("eta = 1 passes straight through and reflects nothing",
          "[stability][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    for (double theta = 0; theta < deg(89); theta += deg(1)) {
        const Vec3 wo = direction_at(theta);
        CHECK(fresnel_dielectric(wo.z, 1) == Approx(0).margin(1e-6));
        const auto wt = refract(wo, kUp, 1);
        REQUIRE(wt);
        CHECK(glm::length(*wt + wo) < 1e-6f);
    }
}

TEST_CASE("The refracted direction is unit, in the plane of incidence, obeys Snell and reverses",
          "[stability][ex:ch07.refract]") {
    Pcg32 rng(11, 3);
    int refracted = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 n =
            glm::normalize(Vec3(rng.next_real() - 0.5f, rng.next_real() - 0.5f, rng.next_real() - 0.5f));
        Vec3 wo =
            glm::normalize(Vec3(rng.next_real() - 0.5f, rng.next_real() - 0.5f, rng.next_real() - 0.5f));
        if (glm::dot(wo, n) < 0) wo = -wo;
        const Real eta = i % 2 ? Real(kEta) : Real(1 / kEta);
        const auto wt = refract(wo, n, eta);
        const Real cos_i = glm::dot(wo, n);
        if (!wt) {
            // Only beyond the critical angle: sin θ_i > η (within rounding).
            CHECK(std::sqrt(1 - cos_i * cos_i) > eta - 1e-5f);
            continue;
        }
        ++refracted;
        CHECK(glm::length(*wt) == Approx(1).margin(1e-6));
        CHECK(std::abs(glm::dot(glm::cross(wo, n), *wt)) < 1e-5f);  // in the plane of wo and n
        CHECK(glm::dot(*wt, n) <= 0);                               // on the other side
        const Real sin_i = glm::length(glm::cross(wo, n)), sin_t = glm::length(glm::cross(*wt, n));
        CHECK(sin_i == Approx(double(eta * sin_t)).margin(2e-5));  // η_i sin θ_i = η_t sin θ_t
        // Light retraces its path. Within 0.6° of the tangent plane (|cos θ_t| < 0.01) the reversal is
        // ill-conditioned in float: cos θ_t = √(cos² θ_t) turns the 1e-7 rounding of cos² θ_t into 1e-5 of
        // the direction (and, closer still, back into total internal reflection); the same for a grazing wo,
        // whose reversal starts at the critical angle. So it is checked away from both.
        if (std::abs(glm::dot(*wt, n)) < 0.01f || cos_i < 0.01f) continue;
        const auto back = refract(*wt, -n, 1 / eta);
        REQUIRE(back);
        CHECK(glm::length(*back - wo) < 1e-4f);
    }
    CHECK(refracted > 10000);
}

TEST_CASE("Flipping the normal (and with it eta) gives the same refraction and reflectance",
          "[stability][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    for (double theta = 0; theta < deg(90); theta += deg(2.5)) {
        for (Real eta : {Real(kEta), Real(1 / kEta)}) {
            const Vec3 wo = direction_at(theta);
            const auto a = refract(wo, kUp, eta);
            const auto b = refract(wo, -kUp, 1 / eta);
            REQUIRE(a.has_value() == b.has_value());
            if (a) CHECK(glm::length(*a - *b) < 1e-6f);
            CHECK(fresnel_dielectric(wo.z, eta) == fresnel_dielectric(-wo.z, 1 / eta));
        }
    }
}

TEST_CASE("R + T = 1, T from the transmission amplitudes", "[stability][ex:ch07.fresnel_exact]") {
    for (double eta : {kEta, 1 / kEta, 1.0, 2.4}) {
        for (double theta = 0; theta < deg(89.5); theta += deg(0.5)) {
            const double R = double(fresnel_dielectric(Real(std::cos(theta)), Real(eta)));
            INFO("eta " << eta << ", theta " << theta * 180 / std::numbers::pi
                        << ": R + T is not 1, so R differs from the share Fresnel's laws reflect (an amplitude, "
                           "or their unpolarised mean, is wrong)");
            CHECK(R + transmittance(std::cos(theta), eta) == Approx(1).margin(2e-6));
        }
    }
}

TEST_CASE("Total internal reflection never yields NaN or a zero direction (glm::refract does, unguarded)",
          "[stability][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    // From inside glass at 60 degrees, beyond the critical angle.
    const Vec3 wo = direction_at(deg(60));
    // The naive vector-library call (its ratio is η_i / η_t): a silent zero vector, whose normalisation is
    // NaN.
    const Vec3 naive = glm::refract(-wo, kUp, Real(kEta));
    CHECK(glm::length(naive) == 0);
    CHECK_FALSE(is_finite(glm::normalize(naive)));
    // This chapter's: no direction, and the sampled BSDF reflects, for every u.
    CHECK_FALSE(refract(wo, kUp, Real(1 / kEta)).has_value());
    for (Real u : {Real(0), Real(0.5), kOneMinusEpsilon}) {
        const DielectricSample s = sample_dielectric(wo, kUp, Real(1 / kEta), u);
        CHECK(s.lobe == DielectricLobe::kReflection);
        CHECK(is_finite(s.wi));
        CHECK(glm::length(s.wi) == Approx(1).margin(1e-6));
        CHECK(s.weight == Color(1));
    }
}

TEST_CASE(
    "Schlick's approximation stays within 0.04 of the exact R, and leaving glass it cuts off at the same "
    "angle",
    "[stability][ex:ch07.fresnel_exact][ex:ch07.fresnel_schlick]") {
    double worst = 0;
    for (double theta = 0; theta <= deg(90); theta += deg(0.1)) {
        const Real c = Real(std::cos(theta));
        worst = std::max(
            worst, double(std::abs(fresnel_schlick(c, Real(kEta)) - fresnel_dielectric(c, Real(kEta)))));
        CHECK((fresnel_schlick(c, Real(1 / kEta)) == 1) == (fresnel_dielectric(c, Real(1 / kEta)) == 1));
    }
    CHECK(worst < 0.04);
    CHECK(worst > 0.03);  // an approximation: the error is real (0.0357 near 85 degrees)
}

// ---------------------------------------------------------------------------------------------------------
// The sampled dielectric and Beer–Lambert

TEST_CASE("The dielectric chooses each lobe by its share of the energy and its weights keep the estimate unbiased",
          "[statistical][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    // Whatever order the lobes take in [0, 1): reflections are chosen with frequency R, and the mean weight a
    // lobe brings back over all samples is what the interface sends that way: R reflected, and T = 1 − R
    // transmitted, scaled as radiance scales across the interface (L / η² is conserved).
    const Vec3 wo = direction_at(deg(35));  // below the critical angle from either side
    for (Real eta : {Real(kEta), Real(1 / kEta)}) {
        const double R = fresnel_dielectric(wo.z, eta);
        Pcg32 rng(5, 9);
        const int n = 200000;
        int reflected = 0;
        double sum_r = 0, sum_r2 = 0, sum_t = 0, sum_t2 = 0;
        for (int i = 0; i < n; ++i) {
            const DielectricSample s = sample_dielectric(wo, kUp, eta, rng.next_real());
            if (s.lobe == DielectricLobe::kReflection) {
                ++reflected;
                CHECK(glm::length(s.wi - Vec3(-wo.x, -wo.y, wo.z)) < 1e-6f);
                sum_r += s.weight.r;
                sum_r2 += double(s.weight.r) * s.weight.r;
            } else {
                CHECK(s.wi.z < 0);
                sum_t += s.weight.r;
                sum_t2 += double(s.weight.r) * s.weight.r;
            }
        }
        INFO("eta " << eta << ", R " << R);
        // Binomial: σ = √(n R (1 − R)); 5σ. The means: 5 standard errors, and a float's rounding.
        const double sigma = std::sqrt(n * R * (1 - R));
        const auto tolerance = [n](double sum, double sum2) {
            return 5 * std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)) / n) + 1e-6;
        };
        {
            INFO(reflected << " reflections in " << n << ": the lobe is not chosen by its share of the energy");
            CHECK(std::abs(reflected - n * R) < 5 * sigma);
        }
        {
            INFO("the mean weight of reflections over all samples is " << sum_r / n << ", not R: the weight of a "
                 "reflection is wrong");
            CHECK(std::abs(sum_r / n - R) < tolerance(sum_r, sum_r2));
        }
        {
            const double expected = (1 - R) / (double(eta) * eta);
            INFO("the mean weight of transmissions over all samples is " << sum_t / n << ", not T / eta^2 = "
                 << expected << ": the weight of a transmission is wrong");
            CHECK(std::abs(sum_t / n - expected) < tolerance(sum_t, sum_t2));
        }
    }
}

TEST_CASE("A dielectric sample reports the probability of its lobe: R for reflection, 1 - R for transmission",
          "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    for (Real eta : {Real(kEta), Real(1 / kEta)}) {
        const Vec3 wo = direction_at(deg(35));
        const Real R = fresnel_dielectric(wo.z, eta);
        int reflections = 0;
        for (Real u : {Real(0), Real(0.25) * R, Real(0.5) * R, Real(0.5) * (1 + R), Real(0.99), kOneMinusEpsilon}) {
            const DielectricSample s = sample_dielectric(wo, kUp, eta, u);
            INFO("eta " << eta << ", u " << u);
            reflections += s.lobe == DielectricLobe::kReflection ? 1 : 0;
            CHECK(s.probability == Approx(s.lobe == DielectricLobe::kReflection ? R : 1 - R));
        }
        CHECK(reflections > 0);
        CHECK(reflections < 6);
    }
}

TEST_CASE("Schlick's approximation is reciprocal and reflects everything beyond the critical angle",
          "[ex:ch07.fresnel_schlick]") {
    // From outside at θ, and from inside at the refracted θ_t: the same reflectance (Schlick takes the angle
    // on the less dense side both ways).
    for (double degrees : {10.0, 30.0, 60.0, 80.0}) {
        const double theta = deg(degrees);
        const double theta_t = std::asin(std::sin(theta) / kEta);
        INFO(degrees << " degrees");
        CHECK(fresnel_schlick(Real(std::cos(theta)), Real(kEta)) ==
              Approx(fresnel_schlick(Real(std::cos(theta_t)), Real(1 / kEta))).epsilon(1e-4));
    }
    // Inside glass, 50° from the normal, beyond the critical angle asin(1 / 1.5) = 41.8°: all reflects.
    CHECK(fresnel_schlick(Real(std::cos(deg(50))), Real(1 / kEta)) == 1);
}

TEST_CASE("Beer-Lambert: exp(-sigma d) per channel, and clear glass passes everything, even at infinity",
          "[stability][ex:ch07.beer_lambert]") {
    const Color t = beer_lambert(Color(0, 1, 2), 0.5f);
    CHECK(t.r == 1);
    CHECK(t.g == Approx(std::exp(-0.5)).epsilon(1e-6));
    CHECK(t.b == Approx(std::exp(-1.0)).epsilon(1e-6));
    CHECK(beer_lambert(Color(0), kInfinity) == Color(1));
    CHECK(beer_lambert(Color(1), kInfinity) == Color(0));
    // Two segments absorb what their sum does.
    const Color a = beer_lambert(Color(0.3f), 2) * beer_lambert(Color(0.3f), 3);
    CHECK(a.r == Approx(double(beer_lambert(Color(0.3f), 5).r)).epsilon(1e-6));
}

// ---------------------------------------------------------------------------------------------------------
// The furnace

// The course's scene `file` prepared for chapter 07's path tracer (chapter 06's loop with this chapter's
// BSDFs), simulating what a run of chapter 07 simulates (run_chapter()'s simulated_effects).
struct SceneTracer {
    explicit SceneTracer(const char* file)
        : scene(load_scene(scene_path(file))),
          prepared(scene, chapter07_effects(scene), refraction_materials()),
          tracer(prepared.world, prepared.materials, prepared.lights, as_run(scene)) {}

    static PathOptions as_run(const Scene& scene) {
        PathOptions options;
        options.simulated = chapter07_effects(scene);
        return options;
    }

    Scene scene;
    RenderScene prepared;
    PathTracer tracer;
};

// Every pixel of the furnace scene: the mean of its samples is 1 within 5 standard errors (and exactly 1
// where every sample is).
void check_furnace(const char* file) {
    const SceneTracer traced(file);
    const Scene& scene = traced.scene;
    const PathTracer& tracer = traced.tracer;
    const int size = 32, spp = 256;
    const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
    RayCounts rays;
    double total = 0;
    int noisy = 0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            double sum = 0, sum2 = 0;
            for (int s = 0; s < spp; ++s) {
                Pcg32 rng = Pcg32::for_sample(std::uint64_t(y * size + x), std::uint64_t(s), 3);
                const Real u = Real(x) + rng.next_real();
                const Real v = Real(y) + rng.next_real();
                const Color L = tracer.radiance(camera_ray(camera, u, v), rng, rays);
                REQUIRE(is_finite(L));
                REQUIRE(L.r == L.g);
                sum += double(L.r);
                sum2 += double(L.r) * double(L.r);
            }
            const double mean = sum / spp;
            const double se = std::sqrt(std::max(0.0, sum2 / spp - mean * mean) / (spp - 1));
            if (se > 0) ++noisy;
            INFO("pixel " << x << ", " << y << ": mean " << mean << ", standard error " << se);
            CHECK(std::abs(mean - 1) <= 5 * se + 1e-5);
            total += mean;
        }
    }
    CHECK(total / (size * size) == Approx(1).margin(0.01));
    CHECK(rays[RayKind::kRefraction] > 0);
    CHECK(rays[RayKind::kShadow] == 0);  // a delta BSDF takes no light samples
    INFO("pixels with noise: " << noisy);
}

TEST_CASE("Furnace: a glass sphere under a uniform environment of radiance 1 renders as 1 everywhere",
          "[furnace][ex:ch01.camera_ray][ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch05.termination]"
          "[ex:ch06.path_tracer][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    check_furnace("ch07_furnace_glass.json");
}

TEST_CASE("Furnace: an eta = 1 sphere renders as exactly 1 everywhere",
          "[furnace][ex:ch01.camera_ray][ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch05.termination]"
          "[ex:ch06.path_tracer][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    check_furnace("ch07_furnace_eta1.json");
}

// ---------------------------------------------------------------------------------------------------------
// Only the effects a scene calls for

const char* kGlassBox = R"({
  "camera": {"from": [278, 278, -800], "at": [278, 278, 0], "up": [0, 1, 0], "vfov": 40},
  "materials": {"white": {"type": "diffuse", "albedo": [0.73, 0.73, 0.73]},
                "lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [15, 15, 15]},
                "glass": {"type": "dielectric", "ior": 1.5}},
  "shapes": [
    {"type": "quad", "origin": [0, 0, 555], "u": [555, 0, 0], "v": [0, 0, -555], "material": "white"},
    {"type": "quad", "origin": [555, 0, 555], "u": [-555, 0, 0], "v": [0, 555, 0], "material": "white"},
    {"type": "quad", "origin": [213, 554, 227], "u": [130, 0, 0], "v": [0, 0, 105], "material": "lamp"},
    {"type": "sphere", "center": [190, 90, 190], "radius": 90, "material": "glass"}
  ]EFFECTS
})";

Scene glass_box(const std::string& effects) {
    std::string json = kGlassBox;
    json.replace(json.find("EFFECTS"), 7, effects);
    return scene_from(json);
}

TEST_CASE("A scene without a dielectric traces no refraction rays",
          "[effects][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    const Scene scene = load_scene(scene_path("ch06_default.json"));
    Renderer used{};
    const RenderResult r = render_scene(scene, small_settings(24, 4), &used);
    CHECK(used == Renderer::kPaths);
    CHECK(r.rays[RayKind::kRefraction] == 0);
    // The glass tracer itself, given that scene, traces none either.
    const RenderResult g =
        render_with(Renderer::kPaths, scene, chapter07_effects(scene), small_settings(24, 4), {});
    CHECK(g.rays[RayKind::kRefraction] == 0);
    CHECK(g.rays[RayKind::kIndirect] > 0);
}

TEST_CASE("A scene calling only for shadows and direct light gets maximum depth 1: no indirect rays",
          "[effects][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch04.direct_light][ex:ch04.lambert]"
          "[ex:ch04.sample_quad_light]") {
    const Scene scene = glass_box(R"(, "effects": ["shadows", "direct"])");
    Renderer used{};
    const RenderResult r = render_scene(scene, small_settings(24, 4), &used);
    CHECK(used == Renderer::kDirect);
    CHECK(r.rays[RayKind::kIndirect] == 0);
    CHECK(r.rays[RayKind::kReflection] == 0);
    CHECK(r.rays[RayKind::kRefraction] == 0);
    CHECK(r.rays[RayKind::kShadow] > 0);
    CHECK(r.rays.total() == r.rays[RayKind::kCamera] + r.rays[RayKind::kShadow]);
}

TEST_CASE(
    "Glass without the indirect effect: refraction rays, and a path ends after its first diffuse bounce",
    "[effects][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
    "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
    "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
    "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch07.dielectric_sample]"
    "[ex:ch07.fresnel_exact][ex:ch07.refract]") {
    const Scene scene = glass_box(R"(, "effects": ["shadows", "direct", "reflection", "refraction"])");
    Renderer used{};
    const RenderResult r = render_scene(scene, small_settings(24, 4), &used);
    CHECK(used == Renderer::kPaths);
    CHECK(r.rays[RayKind::kRefraction] > 0);
    // The one ray that leaves a path's first diffuse vertex is MIS's BSDF sample of the direct light (it
    // counts the lamp it meets, weighted): at most one per camera ray, and the path ends where it lands.
    CHECK(r.rays[RayKind::kIndirect] > 0);
    CHECK(r.rays[RayKind::kIndirect] <= r.rays[RayKind::kCamera]);
    // The same scene with the light strategy (next-event estimation alone) needs no such ray.
    PathOptions light;
    light.strategy = SamplingStrategy::kLight;
    const RenderResult l =
        render_with(Renderer::kPaths, scene, chapter07_effects(scene), small_settings(24, 4), light);
    CHECK(l.rays[RayKind::kIndirect] == 0);
}

// Issue 13's wrong image: an emissive plane as the sky, a diffuse floor and ball, a small glass sphere. The
// plane has infinite area, so no light sampler can draw from it; only paths that hit it see it. Chapter 07's
// old fork counted emission after a diffuse bounce only from sampled lights and lost the sky (mean 0.357
// against 0.694 with the glass made diffuse). `glass` is the sphere's material.
Scene sky_scene(const std::string& glass) {
    return scene_from(R"({
      "camera": {"from": [0, 1.5, 6], "at": [0, 0.8, 0], "up": [0, 1, 0], "vfov": 40},
      "materials": {
        "sky": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [1, 1, 1]},
        "floor": {"type": "diffuse", "albedo": [0.6, 0.6, 0.6]},
        "ball": {"type": "diffuse", "albedo": [0.7, 0.5, 0.3]},
        "glass": )" + glass +
                      R"(},
      "shapes": [
        {"type": "plane", "point": [0, 20, 0], "normal": [0, -1, 0], "material": "sky"},
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
        {"type": "sphere", "center": [-0.8, 0.8, 0], "radius": 0.8, "material": "ball"},
        {"type": "sphere", "center": [0.9, 0.4, 0.8], "radius": 0.4, "material": "glass"}
      ]
    })");
}

TEST_CASE("An emissive plane lights a glass scene as it lights the same scene with the glass made diffuse",
          "[render][regression][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch05.termination][ex:ch06.path_tracer][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact]"
          "[ex:ch07.refract]") {
    const RenderSettings settings = small_settings(32, 64);
    const Scene glass = sky_scene(R"({"type": "dielectric", "ior": 1.5})");
    const Scene diffuse = sky_scene(R"({"type": "diffuse", "albedo": [0.73, 0.73, 0.73]})");
    const RenderResult g = render_scene(glass, settings);
    const RenderResult d = render_scene(diffuse, settings);
    CHECK(g.rays[RayKind::kRefraction] > 0);
    // The small sphere covers a few percent of the image: the two means agree within 3 %, where the lost
    // sky made the glass scene 49 % darker.
    CHECK(g.image.mean() == Approx(d.image.mean()).epsilon(0.03));
    // Index-matched glass (ior 1) is invisible: pixel by pixel the image is the scene without the sphere.
    Scene matched = sky_scene(R"({"type": "dielectric", "ior": 1})");
    Scene without = matched;
    without.shapes.pop_back();
    const RenderResult m = render_scene(matched, settings);
    const RenderResult w = render_scene(without, small_settings(32, 64));
    CHECK(m.image.mean() == Approx(w.image.mean()).epsilon(0.01));
}

TEST_CASE("A glass scene without lights traces no shadow rays",
          "[effects][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch05.termination][ex:ch06.path_tracer][ex:ch07.dielectric_sample]"
          "[ex:ch07.fresnel_exact][ex:ch07.refract]") {
    Scene scene = glass_box("");
    for (Material& m : scene.materials) m.emission = Color(0);
    const RenderResult r =
        render_with(Renderer::kPaths, scene, chapter07_effects(scene), small_settings(24, 4), {});
    CHECK(r.rays[RayKind::kShadow] == 0);
    CHECK(r.rays[RayKind::kRefraction] > 0);
    CHECK(r.image.mean() == 0);
}

// ---------------------------------------------------------------------------------------------------------
// The default scene

TEST_CASE("The default scene renders finite, plausible and the same on 1 and 2 threads",
          "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch07.dielectric_sample]"
          "[ex:ch07.fresnel_exact][ex:ch07.refract]") {
    const Scene scene = load_scene(scene_path("ch07_default.json"));
    RenderSettings settings = small_settings(40, 8);
    Renderer used{};
    const RenderResult a = render_scene(scene, settings, &used);
    settings.threads = 1;
    const RenderResult b = render_scene(scene, settings);
    CHECK(used == Renderer::kPaths);
    CHECK(a.image.all_finite());
    CHECK(a.image.mean() > 0.1);
    CHECK(a.image.mean() < 2);
    CHECK(a.rays[RayKind::kRefraction] > 0);
    CHECK(a.rays[RayKind::kReflection] > 0);
    CHECK(a.image.pixels() == b.image.pixels());
}

TEST_CASE("Path parts: the glass box's estimate split by path kind sums to it and leaves the path as it was",
          "[render][ex:ch01.camera_ray][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch07.dielectric_sample]"
          "[ex:ch07.fresnel_exact][ex:ch07.refract]") {
    const SceneTracer traced("cornell.json");
    const Scene& scene = traced.scene;
    const PathTracer& tracer = traced.tracer;
    const int size = 24, spp = 32;
    const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
    RayCounts rays;
    std::array<double, kPathPartCount> totals{};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            for (int s = 0; s < spp; ++s) {
                const Real u = Real(x) + Real(0.5), v = Real(y) + Real(0.5);
                Pcg32 rng = Pcg32::for_sample(std::uint64_t(y * size + x), std::uint64_t(s), 5);
                Pcg32 same = rng;
                PathParts parts;
                const Color with = tracer.radiance(camera_ray(camera, u, v), rng, rays, &parts);
                const Color without = tracer.radiance(camera_ray(camera, u, v), same, rays);
                REQUIRE(with == without);
                REQUIRE(rng.next_uint() == same.next_uint());  // the same numbers drawn
                Color sum(0);
                for (std::size_t k = 0; k < kPathPartCount; ++k) {
                    sum += parts.parts[k];
                    totals[k] += double(luminance(parts.parts[k]));
                }
                for (int c = 0; c < 3; ++c) CHECK(std::abs(sum[c] - with[c]) <= 1e-5f * (1 + with[c]));
            }
        }
    }
    // The lamp is seen, light sampling lights the walls, and the sphere's caustic is found (the light that
    // BSDF hits weighted by MIS bring is small here, but not zero).
    CHECK(totals[std::size_t(PathPart::kSeen)] > 0);
    CHECK(totals[std::size_t(PathPart::kNextEvent)] > 0);
    CHECK(totals[std::size_t(PathPart::kCaustic)] > 0);
    CHECK(totals[std::size_t(PathPart::kBsdfHit)] > 0);
}

TEST_CASE(
    "Sobol samples, the default: the glass box renders finite, the same on 1 and 2 threads, near stratified",
    "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
    "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
    "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
    "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch07.dielectric_sample]"
    "[ex:ch07.fresnel_exact][ex:ch07.refract]") {
    const Scene scene = load_scene(scene_path("ch07_default.json"));
    RenderSettings settings = small_settings(32, 16);
    PathOptions stratified_points;
    stratified_points.sampler = PointSet::kStratified;
    const EffectSet simulated = chapter07_effects(scene);
    const RenderResult a = render_with(Renderer::kPaths, scene, simulated, settings);
    const RenderResult stratified =
        render_with(Renderer::kPaths, scene, simulated, settings, stratified_points);
    settings.threads = 1;
    const RenderResult b = render_with(Renderer::kPaths, scene, simulated, settings);
    CHECK(PathOptions{}.sampler == PointSet::kSobol);
    CHECK(a.image.all_finite());
    CHECK(a.image.pixels() == b.image.pixels());
    CHECK(a.image.pixels() != stratified.image.pixels());
    // Both unbiased: their image means agree within the noise, measured. One render's mean moves by several
    // per cent with the seed (the sphere's caustic is a few bright paths), so each sampler renders 6 seeds,
    // and the difference of the two averages must be under 4 standard errors.
    auto mean_and_error = [&](const PathOptions& options) {
        double sum = 0, sum2 = 0;
        constexpr int kSeeds = 6;
        for (int seed = 1; seed <= kSeeds; ++seed) {
            settings.seed = std::uint64_t(seed);
            const double m = render_with(Renderer::kPaths, scene, simulated, settings, options).image.mean();
            sum += m;
            sum2 += m * m;
        }
        const double mean = sum / kSeeds, variance = (sum2 / kSeeds - mean * mean) * kSeeds / (kSeeds - 1);
        return std::pair{mean, variance / kSeeds};
    };
    const auto [sobol_mean, sobol_error2] = mean_and_error(PathOptions{});
    const auto [stratified_mean, stratified_error2] = mean_and_error(stratified_points);
    INFO("Sobol " << sobol_mean << ", stratified " << stratified_mean);
    CHECK(std::abs(sobol_mean - stratified_mean) < 4 * std::sqrt(sobol_error2 + stratified_error2));
}

TEST_CASE("Coloured glass absorbs: a sphere with absorption is darker, and redder for a blue-absorbing one",
          "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch07.beer_lambert]"
          "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    Scene scene = glass_box("");
    const RenderSettings settings = small_settings(32, 16);
    const RenderResult before = render_scene(scene, settings);
    for (Material& m : scene.materials) {
        if (m.type == "dielectric") m.absorption = Color(0, 0.01f, 0.02f);  // the sphere: 180 across
    }
    const RenderResult after = render_scene(scene, settings);
    Color b(0), a(0);
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            b += before.image.at(x, y);
            a += after.image.at(x, y);
        }
    }
    CHECK(a.r == Approx(double(b.r)).epsilon(0.02));  // red is not absorbed (same seed, same paths)
    CHECK(a.b < b.b * 0.97f);
    CHECK(a.g < b.g);
}

TEST_CASE("With and without next-event estimation the glass box converges to the same image",
          "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch07.dielectric_sample]"
          "[ex:ch07.fresnel_exact][ex:ch07.refract]") {
    const Scene scene = glass_box("");
    RenderSettings settings = small_settings(16, 512);
    PathOptions nee, hits;
    hits.strategy = SamplingStrategy::kBrdf;
    const RenderResult a = render_with(Renderer::kPaths, scene, chapter07_effects(scene), settings, nee);
    settings.seed = 8;
    const RenderResult b = render_with(Renderer::kPaths, scene, chapter07_effects(scene), settings, hits);
    CHECK(a.rays[RayKind::kShadow] > 0);
    CHECK(b.rays[RayKind::kShadow] == 0);
    // The image means (256 pixels × 512 paths each): within 3 % (the light-hitting estimate is the noisier).
    CHECK(b.image.mean() == Approx(a.image.mean()).epsilon(0.03));
}

TEST_CASE("Radiance inside glass is eta^2 times the radiance outside: a camera inside sees 2.25",
          "[furnace][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch05.termination][ex:ch06.path_tracer][ex:ch07.dielectric_sample]"
          "[ex:ch07.fresnel_exact][ex:ch07.refract]") {
    // The camera at the centre of a glass sphere under a uniform environment of radiance 1. What is conserved
    // across the interface is L / η², so the radiance inside is 1.5² = 2.25 in every direction; without the
    // 1 / η² factor of the BTDF every pixel would be 1.
    const Scene scene = scene_from(R"({
      "camera": {"from": [0, 0, 0], "at": [0, 0, -1], "up": [0, 1, 0], "vfov": 90},
      "materials": {"glass": {"type": "dielectric", "ior": 1.5}},
      "shapes": [{"type": "sphere", "center": [0.1, -0.2, 0.05], "radius": 1, "material": "glass"}],
      "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
    })");
    const RenderResult r =
        render_with(Renderer::kPaths, scene, chapter07_effects(scene), small_settings(16, 16), {});
    for (const Color& c : r.image.pixels()) CHECK(c.g == Approx(2.25).epsilon(1e-5));
    CHECK(r.rays[RayKind::kRefraction] > 0);
}

// ---------------------------------------------------------------------------------------------------------
// Rough glass (rough_dielectric.hpp) and the chi-square tests of this chapter's samplers

namespace {

using namespace rt::test;

// Every chi-square test of this file: rough glass 24 (3 roughnesses × 2 η × 4 directions), the smooth
// dielectric's choice of lobe 1, rough metal 6 (3 roughnesses × 2 directions), coated diffuse 3 (3
// directions). Each runs at the Šidák-corrected level for 34.
const double kAlphaPerTest = sidak_level(34);

// The rough-glass tests put the normal along +x and wo in the x–y plane: both lobes (in the plane of
// incidence) then lie along the equator of the chi-square's (z, φ) grid, where its cells are smallest in
// angle, and not at its pole.
const Vec3 kSide{1, 0, 0};

Vec3 outgoing_at(double theta) {
    return {Real(std::cos(theta)), Real(std::sin(theta)), 0};
}

// sample() as a chi-square sampler: u from the harness, u_lobe from the sampler's own generator.
DirectionSampler rough_sampler(const Bsdf& bsdf, const Vec3& wo, const Vec3& n, std::uint64_t seed) {
    auto lobe = std::make_shared<Pcg32>(seed, 23);
    return [&bsdf, wo, n, lobe](Vec2 u) {
        const BsdfSample s = bsdf.sample(wo, n, u, lobe->next_real());
        return Drawn{s.wi, double(s.pdf), !(s.pdf > 0)};
    };
}

// ∫ f |cos θ_i| dω_i for wo, by sampling: the mean of f |cos θ_i| / pdf (0 for a lost sample), the largest
// single weight, and the standard error.
struct Albedo {
    double mean = 0, largest = 0, error = 0;
};
Albedo albedo_of(const Bsdf& bsdf, const Vec3& wo, const Vec3& n, int samples, std::uint64_t seed) {
    Pcg32 rng(seed, 5);
    double sum = 0, sum2 = 0;
    Albedo a;
    for (int k = 0; k < samples; ++k) {
        const Vec2 u = rng.next_vec2();
        const BsdfSample s = bsdf.sample(wo, n, u, rng.next_real());
        double w = 0;
        if (s.pdf > 0) w = double(s.f.g) * double(scattering_cosine(s.wi, n, s.transmitted)) / double(s.pdf);
        sum += w;
        sum2 += w * w;
        a.largest = std::max(a.largest, w);
    }
    a.mean = sum / samples;
    a.error = std::sqrt(std::max(0.0, sum2 / samples - a.mean * a.mean) / (samples - 1));
    return a;
}

// A frosted sphere (radius 1, ior 1.5) alone under a uniform sky of radiance 1, seen whole (vfov 35 from 4).
Scene frosted_sphere(double roughness) {
    std::string json = R"({
      "camera": {"from": [0, 0, 4], "at": [0, 0, 0], "up": [0, 1, 0], "vfov": 35},
      "materials": {"glass": {"type": "dielectric", "ior": 1.5ROUGHNESS}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass"}],
      "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
    })";
    const std::string r = roughness > 0 ? ", \"roughness\": " + std::to_string(roughness) : "";
    json.replace(json.find("ROUGHNESS"), 9, r);
    return scene_from(json);
}

// The furnace image with chapter 06's loop (render_with), and the mean over the pixels that see the sphere
// (every pixel whose centre ray hits it) with its standard error over those pixels.
struct Furnace {
    RenderResult render;
    double sphere_mean = 0, sphere_error = 0;
    int sphere_pixels = 0;
};
Furnace render_furnace(double roughness, int size, int spp, std::uint64_t seed) {
    const Scene scene = frosted_sphere(roughness);
    RenderSettings settings = small_settings(size, spp);
    settings.seed = seed;
    // What a run of chapter 07 simulates for the scene, as its executable renders it.
    Furnace f{render_scene(scene, settings), 0, 0, 0};
    const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
    double sum = 0, sum2 = 0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const Ray ray = camera_ray(camera, Real(x) + 0.5f, Real(y) + 0.5f);
            // The sphere at the origin, radius 1: hit when the ray passes within 0.98 of its centre (pixels
            // on its rim also see the sky).
            const Vec3 closest = ray.origin + glm::dot(-ray.origin, ray.direction) * ray.direction;
            if (glm::length(closest) > 0.98f) continue;
            const double v = double(f.render.image.at(x, y).g);
            sum += v;
            sum2 += v * v;
            ++f.sphere_pixels;
        }
    }
    f.sphere_mean = sum / f.sphere_pixels;
    f.sphere_error = std::sqrt(std::max(0.0, sum2 / f.sphere_pixels - f.sphere_mean * f.sphere_mean) /
                               (f.sphere_pixels - 1));
    return f;
}

}  // namespace

TEST_CASE(
    "Rough glass: sample() fits pdf() by chi-square over the whole sphere, for roughness 0.1, 0.3 and "
    "0.7, eta 1.5 and 1 / 1.5, wo at 0, 45, 70 and 88 degrees, and the pdf integrates to what is not "
    "lost",
    "[statistical][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    std::uint64_t seed = 700;
    for (double roughness : {0.1, 0.3, 0.7}) {
        for (double eta : {kEta, 1 / kEta}) {
            const RoughDielectric glass(Real(roughness), Real(eta), Transport::kRadiance);
            for (double degrees : {0.0, 45.0, 70.0, 88.0}) {
                INFO("roughness " << roughness << ", eta " << eta << ", wo at " << degrees << " degrees");
                const Vec3 wo = outgoing_at(deg(degrees));
                ++seed;
                const ChiSquare r = test_directions(
                    rough_sampler(glass, wo, kSide, seed),
                    [&](const Vec3& wi) { return double(glass.pdf(wo, wi, kSide)); }, seed);
                require_fit_with_losses(r, kAlphaPerTest);
            }
        }
    }
}

TEST_CASE(
    "Rough glass: with wo along the normal and roughness 0.1 nothing is lost and the pdf integrates to 1",
    "[statistical][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    // Entering (η = 1.5) from along n no refraction leaves above the surface, and a reflection goes below
    // only off a facet tilted past 45°: probability α² / (1 + α²) = 1e-4 of the facets, times F ≈ 0.04.
    const RoughDielectric glass(Real(0.1), Real(kEta), Transport::kRadiance);
    const ChiSquare r = test_directions(
        rough_sampler(glass, kSide, kSide, 760),
        [&](const Vec3& wi) { return double(glass.pdf(kSide, wi, kSide)); }, 760);
    INFO("integral " << r.expected_total / r.samples << ", lost " << r.lost);
    CHECK(r.expected_total / r.samples == Approx(1).margin(1e-3));
    CHECK(r.lost <= 20);
    CHECK(r.bad_samples == 0);
}

TEST_CASE("Rough glass: the pdf and f a sample returns are what pdf() and eval() give for its direction",
          "[statistical][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    Pcg32 rng(770, 1);
    int checked = 0;
    for (int k = 0; k < 20000; ++k) {
        const Real roughness = Real(0.05) + Real(0.95) * rng.next_real();
        const Real eta = k % 2 ? Real(kEta) : Real(1 / kEta);
        const RoughDielectric glass(roughness, eta, k % 3 ? Transport::kRadiance : Transport::kImportance);
        const Vec3 n = random_unit(rng);
        Vec3 wo = random_unit(rng);
        if (glm::dot(wo, n) < 0) wo = -wo;
        const Vec2 u = rng.next_vec2();
        const BsdfSample s = glass.sample(wo, n, u, rng.next_real());
        if (!(s.pdf > 0)) continue;
        ++checked;
        CHECK(s.pdf == glass.pdf(wo, s.wi, n));
        CHECK(s.f == glass.eval(wo, s.wi, n));
        CHECK(s.transmitted == (glm::dot(s.wi, n) < 0));
        CHECK_FALSE(s.delta);
    }
    CHECK(checked > 15000);
    CHECK_FALSE(RoughDielectric(Real(0.3), Real(kEta), Transport::kRadiance).flags().delta);
    CHECK(RoughDielectric(Real(0.3), Real(kEta), Transport::kRadiance).flags().transmission);
}

TEST_CASE(
    "Rough glass: reflection is symmetric, transmission obeys f_t(wo, wi) / eta_o^2 = f_t(wi, wo) / "
    "eta_i^2 for radiance, and the importance BTDF is the radiance one with its arguments swapped",
    "[stability][ex:ch07.fresnel_exact]") {
    Pcg32 rng(780, 1);
    int transmitted = 0;
    for (int k = 0; k < 20000; ++k) {
        const Real roughness = Real(0.1) + Real(0.9) * rng.next_real();
        const RoughDielectric outside(roughness, Real(kEta), Transport::kRadiance);
        const RoughDielectric inside(roughness, Real(1 / kEta), Transport::kRadiance);
        const RoughDielectric outside_importance(roughness, Real(kEta), Transport::kImportance);
        Vec3 wo = random_unit(rng), wi = random_unit(rng);
        if (wo.z < 0) wo = -wo;  // wo outside (η_o = 1), n = +z
        const double f = double(outside.eval(wo, wi, kUp).g);
        if (wi.z > 0) {
            CHECK(f == Approx(double(outside.eval(wi, wo, kUp).g)).epsilon(1e-4).margin(1e-6));
            continue;
        }
        // wi inside (η_i = 1.5): seen from there the normal is −z and η = 1 / 1.5.
        const double back = double(inside.eval(wi, wo, -kUp).g);
        transmitted += f > 0;
        CHECK(f / 1 == Approx(back / (kEta * kEta)).epsilon(1e-3).margin(1e-6));
        CHECK(double(outside_importance.eval(wo, wi, kUp).g) == Approx(back).epsilon(1e-3).margin(1e-6));
    }
    CHECK(transmitted > 1000);
}

TEST_CASE(
    "Rough glass conserves energy: the integral of f |cos| is at most 1 for every wo, and single "
    "scattering loses a little, more at grazing angles and high roughness",
    "[statistical][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    // Importance is what is conserved when wo is the direction light comes from (chapter 08), so ∫ f |cos|
    // over wi must be at most 1 whichever side wo is on. Each sample weighs G1(wi) <= 1 (reflection and
    // transmission alike), so no single weight may pass 1. For radiance the transmitted part is that divided
    // by η²: at most 1 entering glass, up to 2.25 leaving it (radiance inside is η² times brighter).
    std::uint64_t seed = 800;
    for (double roughness : {0.1, 0.3, 0.7, 1.0}) {
        for (double eta : {kEta, 1 / kEta}) {
            const RoughDielectric glass(Real(roughness), Real(eta), Transport::kImportance);
            const RoughDielectric radiance(Real(roughness), Real(eta), Transport::kRadiance);
            for (double degrees = 0; degrees < 90; degrees += 5) {
                const double theta = deg(std::min(degrees, 89.0));
                INFO("roughness " << roughness << ", eta " << eta << ", wo at "
                                  << theta * 180 / std::numbers::pi);
                const Albedo a = albedo_of(glass, direction_at(theta), kUp, 20000, ++seed);
                CHECK(a.largest <= 1 + 1e-5);
                CHECK(a.mean <= 1);
                // Not everything lost: the least is 0.34 (roughness 1, from inside at 80°, where facets
                // tilted past 45° send most light back into the glass below the surface, lost to single
                // scattering).
                CHECK(a.mean > 0.3);
                const Albedo r = albedo_of(radiance, direction_at(theta), kUp, 20000, seed);
                if (eta > 1) CHECK(r.largest <= 1 + 1e-5);
            }
        }
    }
    // What is lost: nearly nothing at normal incidence for roughness 0.3, a real part at 89° for roughness 1.
    const Albedo normal =
        albedo_of(RoughDielectric(Real(0.3), Real(kEta), Transport::kImportance), kUp, kUp, 100000, 890);
    const Albedo grazing = albedo_of(RoughDielectric(Real(1.0), Real(kEta), Transport::kImportance),
                                     direction_at(deg(89)), kUp, 100000, 891);
    INFO("albedo at 0 degrees, roughness 0.3: " << normal.mean
                                                << "; at 89 degrees, roughness 1: " << grazing.mean);
    CHECK(normal.mean > 0.995);
    CHECK(grazing.mean < 0.9);
}

TEST_CASE(
    "Rough glass stays finite at grazing angles, the critical angle, wo along n, tiny and full "
    "roughness, and eta = 1",
    "[stability][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    const double critical = std::asin(1 / kEta);
    Pcg32 rng(900, 1);
    for (double roughness : {1e-7, 1e-4, 1e-2, 0.5, 1.0}) {
        for (double eta : {kEta, 1 / kEta, 1.0}) {
            for (Transport transport : {Transport::kRadiance, Transport::kImportance}) {
                const RoughDielectric glass(Real(roughness), Real(eta), transport);
                for (double theta : {0.0, critical - 1e-6, critical, critical + 1e-6, deg(89.9), deg(90)}) {
                    INFO("roughness " << roughness << ", eta " << eta << ", theta " << theta);
                    const Vec3 wo = direction_at(theta);
                    for (int k = 0; k < 200; ++k) {
                        const Vec2 u = k == 0 ? Vec2(0) : k == 1 ? Vec2(kOneMinusEpsilon) : rng.next_vec2();
                        const Real u_lobe = k == 2 ? kOneMinusEpsilon : rng.next_real();
                        const BsdfSample s = glass.sample(wo, kUp, u, u_lobe);
                        REQUIRE(is_finite(s.f));
                        REQUIRE(std::isfinite(s.pdf));
                        REQUIRE(s.pdf >= 0);
                        if (s.pdf > 0) {
                            REQUIRE(glm::length(s.wi) == Approx(1).margin(1e-5));
                            REQUIRE(std::isfinite(double(s.f.g) / double(s.pdf)));
                        }
                        const Vec3 wi = random_unit(rng);
                        REQUIRE(is_finite(glass.eval(wo, wi, kUp)));
                        REQUIRE(std::isfinite(glass.pdf(wo, wi, kUp)));
                        // The mirror and the straight-through directions, where the half vectors degenerate.
                        for (const Vec3& d : {Vec3(-wo.x, -wo.y, wo.z), -wo, kUp, -kUp}) {
                            REQUIRE(is_finite(glass.eval(wo, d, kUp)));
                            REQUIRE(std::isfinite(glass.pdf(wo, d, kUp)));
                        }
                    }
                }
            }
        }
    }
    // Beyond the critical angle from inside, every facet near n reflects: at roughness 0.01 nothing refracts.
    const RoughDielectric inside(Real(0.1), Real(1 / kEta), Transport::kRadiance);
    for (int k = 0; k < 1000; ++k) {
        const BsdfSample s = inside.sample(direction_at(deg(60)), kUp, rng.next_vec2(), rng.next_real());
        CHECK_FALSE(s.transmitted);
    }
    // Tangent to the surface, or below it (rounding), wo scatters nothing.
    const RoughDielectric glass(Real(0.3), Real(kEta), Transport::kRadiance);
    const Vec3 tangent{1, 0, 0}, below = glm::normalize(Vec3(1, 0, -1e-6f));
    CHECK(glass.sample(tangent, kUp, Vec2(0.5f), 0.5f).pdf == 0);
    CHECK(glass.sample(below, kUp, Vec2(0.5f), 0.5f).pdf == 0);
    CHECK(glass.eval(tangent, kUp, kUp) == Color(0));
    CHECK(glass.pdf(below, kUp, kUp) == 0);
}

TEST_CASE(
    "The smooth dielectric reflects with probability fresnel_dielectric by chi-square over angles and "
    "both lobes, from outside and inside, and transmits nothing beyond the critical angle",
    "[statistical][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    // Each sample picks one of 2 × 30 angles (θ in 3° steps from 1.5°, η = 1.5 and 1 / 1.5) at random, then
    // the smooth dielectric's lobe: the counts per (angle, lobe) are multinomial, expecting N / 60 R and
    // N / 60 (1 − R).
    constexpr int kAngles = 30, kCases = 2 * kAngles, kDraws = 600000;
    std::vector<double> observed(2 * kCases, 0), expected(2 * kCases, 0);
    const SmoothDielectric outside(Real(kEta), Transport::kRadiance),
        inside(Real(1 / kEta), Transport::kRadiance);
    Pcg32 rng(950, 1);
    int transmitted_in_tir = 0;
    for (int c = 0; c < kCases; ++c) {
        const Real eta = c < kAngles ? Real(kEta) : Real(1 / kEta);
        const Real R = fresnel_dielectric(direction_at(deg(1.5 + 3 * (c % kAngles))).z, eta);
        expected[std::size_t(2 * c)] = kDraws / double(kCases) * double(R);
        expected[std::size_t(2 * c + 1)] = kDraws / double(kCases) * (1 - double(R));
    }
    for (int k = 0; k < kDraws; ++k) {
        const int c = std::min(kCases - 1, int(rng.next_real() * kCases));
        const Vec3 wo = direction_at(deg(1.5 + 3 * (c % kAngles)));
        const BsdfSample s = (c < kAngles ? outside : inside).sample(wo, kUp, Vec2(0), rng.next_real());
        observed[std::size_t(2 * c + (s.transmitted ? 1 : 0))] += 1;
        if (s.transmitted && expected[std::size_t(2 * c + 1)] == 0) ++transmitted_in_tir;
    }
    const ChiSquare r = chi_square(observed, expected);
    INFO("chi-square " << r.statistic << ", " << r.dof << " dof, p = " << r.p_value);
    CHECK(r.p_value > kAlphaPerTest);
    CHECK(r.dof > 40);
    CHECK(transmitted_in_tir == 0);
}

TEST_CASE(
    "Furnace: a frosted sphere (roughness 0.3, ior 1.5) under a uniform sky of radiance 1 loses only "
    "what single-scattering microfacets lose",
    "[furnace][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable]"
    "[ex:ch03.robust_offset][ex:ch04.cosine_hemisphere][ex:ch05.termination][ex:ch06.mis_weight]"
    "[ex:ch06.path_tracer][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    const Furnace f = render_furnace(0.3, 32, 256, 11);
    INFO("sphere pixels " << f.sphere_pixels << ", mean " << f.sphere_mean << " +- " << f.sphere_error
                          << ", image mean " << f.render.image.mean());
    CHECK(f.render.image.all_finite());
    CHECK(f.sphere_pixels > 300);
    CHECK(f.render.rays[RayKind::kRefraction] > 0);
    CHECK(f.render.rays[RayKind::kShadow] > 0);  // not a delta: the sky is sampled at every vertex (MIS)
    // Measured (32 × 32 pixels, 256 paths each, seed 11): the sphere's 524 pixels average 0.949 ± 0.002, a
    // loss of 5.1 %; the image 0.971. The bounds:
    //   above, 1: single scattering only loses. Every sample weighs G1(wi) <= 1 (times 1 / η² going in and η²
    //     coming out, which cancel on a path that leaves the sphere), so no pixel may pass 1 beyond noise
    //     (Russian roulette lets one sample pass 1): 5 σ, σ measured from a second image;
    //   below, 0.90: a path that meets the sphere meets its surface about 2.4 times (this render's refraction
    //     and reflection rays, 322k, per camera ray that hits it, 134k), and single scattering at roughness
    //     0.3 loses at most 0.3 % from outside below 60° and at most 4 % from inside below 70° (the energy
    //     test's albedo: 0.999 to 0.997 and 0.991 to 0.962; the grazing rim, where it loses up to 15 %, is a
    //     small part of the disc): 2.4 × 4 % ≈ 10 %.
    // And the loss is real: the mean is below 1 by more than 5 standard errors.
    // The pixel noise σ from a second image of another seed: the difference of two pixels has variance 2σ².
    const Furnace again = render_furnace(0.3, 32, 256, 13);
    double d2 = 0, brightest = 0;
    for (std::size_t i = 0; i < f.render.image.pixels().size(); ++i) {
        const double a = double(f.render.image.pixels()[i].g), b = double(again.render.image.pixels()[i].g);
        d2 += (a - b) * (a - b);
        brightest = std::max({brightest, a, b});
    }
    const double sigma = std::sqrt(d2 / (2.0 * double(f.sphere_pixels)));  // the sky's pixels are exactly 1
    INFO("brightest pixel " << brightest << ", pixel noise " << sigma);
    CHECK(brightest <= 1 + 5 * sigma);
    CHECK(5 * sigma < 0.2);  // measured σ = 0.026: the bound stays within 20 % of 1
    CHECK(f.sphere_mean >= 0.90);
    CHECK(f.sphere_mean + 5 * f.sphere_error < 1);
    CHECK(f.render.image.mean() < 1);
}

TEST_CASE("Furnace: as the roughness goes to 0 the frosted sphere approaches the smooth one",
          "[furnace][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch04.cosine_hemisphere][ex:ch05.termination][ex:ch06.mis_weight]"
          "[ex:ch06.path_tracer][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    const Furnace smooth = render_furnace(0, 24, 128, 12);
    double previous_loss = 1;
    // The loss falls with the roughness, each step by more than 3 standard errors, and at roughness 0.02
    // (α = 4e-4) it is within noise of none.
    for (double roughness : {0.5, 0.3, 0.1, 0.02}) {
        const Furnace rough = render_furnace(roughness, 24, 128, 12);
        const double loss = smooth.sphere_mean - rough.sphere_mean;
        const double se = std::hypot(smooth.sphere_error, rough.sphere_error);
        INFO("roughness " << roughness << ": sphere mean " << rough.sphere_mean << ", smooth "
                          << smooth.sphere_mean << ", loss " << loss << " +- " << se);
        // Measured (24 × 24, 128 paths, seed 12): losses 0.208, 0.046, 0.0031 and 0.0005 ± 0.0006.
        if (roughness > 0.05) {
            CHECK(loss < previous_loss - 3 * se);
        } else {
            CHECK(std::abs(loss) < 4 * se);
        }
        previous_loss = loss;
    }
}

TEST_CASE("A frosted sphere under a sky calls for direct and indirect light, and renders lit with them",
          "[effects][furnace][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch04.cosine_hemisphere][ex:ch05.termination][ex:ch06.mis_weight]"
          "[ex:ch06.path_tracer][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    // Rough glass is no delta: light sampling reaches it, so needed() must turn on what samples the sky.
    const Scene scene = frosted_sphere(0.3);
    const EffectSet effects = needed(scene);
    CHECK(effects.contains(Effect::kDirect));
    CHECK(effects.contains(Effect::kIndirect));
    CHECK(effects.contains(Effect::kRefraction));
    // Rendered with the effects it calls for, the sphere fills most of the image and loses only the few
    // percent single-scattering microfacets lose (simulating only camera, reflection and refraction, as
    // needed() did before it counted rough glass, the same scene renders 0.473 at 32x32, 64 spp).
    const RenderResult r = render_scene(scene, small_settings(16, 64));
    CHECK(r.image.mean() > 0.9);
    CHECK(r.image.mean() < 1.01);
}

TEST_CASE("The depth study's CSV holds one row per depth in named columns", "[depth_study]") {
    const std::vector<GlassDepthRow> rows{{1, 0.075, 0.119, -0.0416, 0.125, 2399809},
                                          {16, 0.0296, 0.0193, -0.0002, 0.793, 13905481}};
    const auto path =
        std::filesystem::temp_directory_path() / ("rt_depth_study_" + std::to_string(getpid()) + ".csv");
    write_glass_depth_csv(rows, 64, path);
    std::ifstream file(path);
    const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    std::filesystem::remove(path);
    CHECK(text ==
          "max_depth,spp,rmse,relative_mse,mean_error,seconds,rays\n"
          "1,64,0.075,0.119,-0.0416,0.125,2399809\n"
          "16,64,0.0296,0.0193,-0.0002,0.793,13905481\n");
    CHECK_THROWS_AS(write_glass_depth_csv(rows, 64, "/nonexistent-folder/x.csv"), InputError);
}

// ---------------------------------------------------------------------------------------------------------
// Conductors (conductor.hpp, fresnel.hpp's fresnel_conductor)

namespace {

const ConductorPreset& gold() {
    return kConductorPresets[0];
}

// A perfect reflector: η = 0, k = 1 is the index of a lossless plasma, whose reflectance is 1 at every angle.
const Color kPerfectEta{0}, kPerfectK{1};

// ∫ f cos θ_i dω_i over the sphere by the chi-square harness's adaptive integration (green channel), on a
// grid of a quarter of the chi-square's cells (the adaptive rule refines where the lobe is sharp).
double albedo_by_quadrature(const Bsdf& bsdf, const Vec3& wo, const Vec3& n) {
    const std::vector<double> cells = expected_counts(
        SphereGrid{24, 48},
        [&](const Vec3& wi) {
            return double(bsdf.eval(wo, wi, n).g) * std::max(0.0, double(glm::dot(wi, n)));
        },
        1.0);
    double sum = 0;
    for (double c : cells) sum += c;
    return sum;
}

}  // namespace

TEST_CASE(
    "Conductor Fresnel: at k = 0 it is the dielectric's, at normal incidence the closed form, 1 at grazing",
    "[ch07][ex:ch07.fresnel_conductor][ex:ch07.fresnel_exact]") {
    for (double eta : {1.2, 1.5, 2.4, 1 / 1.5, 1 / 2.4}) {
        for (int i = 0; i <= 100; ++i) {
            const Real c = Real(i) / 100;
            INFO("eta " << eta << ", cos " << c);
            CHECK(fresnel_conductor(c, Real(eta), 0) ==
                  Approx(fresnel_dielectric(c, Real(eta))).margin(2e-6));
        }
    }
    for (const ConductorPreset& metal : kConductorPresets) {
        for (int ch = 0; ch < 3; ++ch) {
            const double e = metal.eta[ch], k = metal.k[ch];
            const double normal = ((e - 1) * (e - 1) + k * k) / ((e + 1) * (e + 1) + k * k);
            CHECK(fresnel_conductor(1, metal.eta[ch], metal.k[ch]) == Approx(normal).epsilon(1e-6));
            CHECK(fresnel_conductor(0, metal.eta[ch], metal.k[ch]) == 1);
            CHECK(fresnel_conductor(Real(1e-3), metal.eta[ch], metal.k[ch]) > 0.99);
        }
        // The stand-in colour of chapters 03 to 06 is this reflectance at normal incidence.
        Material m;
        m.type = "conductor";
        m.eta = metal.eta;
        m.k = metal.k;
        const Color f0 = fresnel_conductor(1, metal.eta, metal.k);
        for (int ch = 0; ch < 3; ++ch) CHECK(stand_in_albedo(m)[ch] == Approx(f0[ch]).epsilon(1e-6));
    }
    // Gold is yellow: it reflects red best and blue worst, at every angle short of grazing.
    for (Real c : {1.0f, 0.7f, 0.3f}) {
        const Color f = fresnel_conductor(c, gold().eta, gold().k);
        CHECK(f.r > f.g);
        CHECK(f.g > f.b);
    }
    // The perfect reflector reflects everything at every angle.
    for (int i = 0; i <= 20; ++i) CHECK(fresnel_conductor(Real(i) / 20, 0, 1) == Approx(1).margin(1e-6));
}

TEST_CASE(
    "Rough metal: sample() fits pdf() by chi-square over the whole sphere for roughness 0.1, 0.3 and 0.7, wo "
    "at 0 and 70 degrees, and the pdf integrates to what is not lost",
    "[statistical][ex:ch07.fresnel_conductor]") {
    std::uint64_t seed = 3100;
    for (double roughness : {0.1, 0.3, 0.7}) {
        const Conductor metal(gold().eta, gold().k, Real(roughness));
        for (double degrees : {0.0, 70.0}) {
            INFO("roughness " << roughness << ", wo at " << degrees << " degrees");
            const Vec3 wo = outgoing_at(deg(degrees));
            ++seed;
            const ChiSquare r = test_directions(
                rough_sampler(metal, wo, kSide, seed),
                [&](const Vec3& wi) { return double(metal.pdf(wo, wi, kSide)); }, seed);
            require_fit_with_losses(r, kAlphaPerTest);
        }
    }
}

TEST_CASE("Rough metal: a sample's f and pdf are eval()'s and pdf()'s, and f is reciprocal",
          "[ch07][ex:ch07.fresnel_conductor]") {
    Pcg32 rng(3200, 1);
    int checked = 0;
    for (int k = 0; k < 20000; ++k) {
        const Conductor metal(kConductorPresets[std::size_t(k % 3)].eta,
                              kConductorPresets[std::size_t(k % 3)].k,
                              Real(0.05) + Real(0.95) * rng.next_real());
        const Vec3 n = random_unit(rng);
        Vec3 wo = random_unit(rng);
        if (glm::dot(wo, n) < 0) wo = -wo;
        const BsdfSample s = metal.sample(wo, n, rng.next_vec2(), 0);
        if (!(s.pdf > 0)) continue;
        ++checked;
        CHECK(s.pdf == metal.pdf(wo, s.wi, n));
        CHECK(s.f == metal.eval(wo, s.wi, n));
        CHECK(glm::dot(s.wi, n) > 0);
        CHECK_FALSE(s.delta);
        const Color back = metal.eval(s.wi, wo, n);
        for (int ch = 0; ch < 3; ++ch) CHECK(back[ch] == Approx(s.f[ch]).epsilon(1e-3));
    }
    CHECK(checked > 15000);  // most samples leave above the surface (grazing wo at roughness 1 loses some)
}

TEST_CASE(
    "White furnace of a perfect reflector: the albedo by sampling is the albedo by quadrature, 1 when "
    "smooth, and falls with roughness (single scattering's loss)",
    "[ch07][ex:ch07.fresnel_conductor][statistical]") {
    std::uint64_t seed = 3300;
    for (double degrees : {0.0, 45.0, 75.0}) {
        const Vec3 wo = direction_at(deg(degrees));
        // Smooth: a delta lobe whose weight is F = 1 exactly.
        const BsdfSample smooth = Conductor(kPerfectEta, kPerfectK, 0).sample(wo, kUp, {0.5f, 0.5f}, 0);
        CHECK(smooth.delta);
        CHECK(double(smooth.f.g) * double(glm::dot(smooth.wi, kUp)) == Approx(1).margin(1e-6));
        double previous = 1;
        for (double roughness : {0.1, 0.3, 0.5, 0.7, 1.0}) {
            INFO("wo at " << degrees << " degrees, roughness " << roughness);
            const Conductor metal(kPerfectEta, kPerfectK, Real(roughness));
            const Albedo a = albedo_of(metal, wo, kUp, 100000, ++seed);
            if (roughness == 0.3 || roughness == 1.0) {  // the quadrature is the slow part: two of five
                CHECK(std::abs(a.mean - albedo_by_quadrature(metal, wo, kUp)) <= 5 * a.error + 1e-4);
            }
            CHECK(a.largest <= 1 + 1e-5);  // the weight F G2 / G1(wo) never exceeds F
            CHECK(a.mean <= 1 + 5 * a.error);
            CHECK(a.mean < previous + 5 * a.error);
            previous = a.mean;
        }
        CHECK(previous < 0.97);  // at roughness 1 the loss is a few per cent or more
    }
    // At normal incidence and α = 1 the facets' normals are cosine-distributed: those tilted past 45° reflect
    // below the surface, the others keep G1(wi) = 2 cos θ_i / (1 + cos θ_i), and E = ∫₀¹ c / (1 + c) dc =
    // 1 − ln 2 exactly (c = cos θ_i).
    const Albedo normal = albedo_of(Conductor(kPerfectEta, kPerfectK, 1), kUp, kUp, 400000, 3399);
    CHECK(std::abs(normal.mean - (1 - std::log(2.0))) <= 5 * normal.error);
}

TEST_CASE("Rough metal tends to the smooth conductor (a mirror with Fresnel's colour) as roughness -> 0",
          "[ch07][ex:ch07.fresnel_conductor][ex:ch04.mirror]") {
    const Conductor smooth(gold().eta, gold().k, 0);
    for (double degrees : {0.0, 30.0, 60.0, 80.0}) {
        const Vec3 wo = direction_at(deg(degrees));
        const BsdfSample mirror = smooth.sample(wo, kUp, {0.5f, 0.5f}, 0);
        const MirrorBrdf ideal(Color(1));
        CHECK(mirror.wi == ideal.sample(wo, kUp, {0.5f, 0.5f}, 0).wi);
        const Color weight = mirror.f * glm::dot(mirror.wi, kUp);
        for (double roughness : {0.01, 0.03}) {
            const Conductor metal(gold().eta, gold().k, Real(roughness));
            Pcg32 rng(3400, 1);
            Color mean(0);
            // GGX has long tails (P(tan θ_m > t) = α² / (α² + t²)): 99 % of the facets lie within
            // tan θ_m < 10 α, and the reflection turns by at most twice the facet's tilt.
            int near_mirror = 0;
            constexpr int kSamples = 20000;
            for (int i = 0; i < kSamples; ++i) {
                const BsdfSample s = metal.sample(wo, kUp, rng.next_vec2(), 0);
                if (!(s.pdf > 0)) continue;
                mean += s.f * glm::dot(s.wi, kUp) / s.pdf / Real(kSamples);
                const double angle = std::acos(std::min(1.0, double(glm::dot(s.wi, mirror.wi))));
                near_mirror += angle < 20 * metal.alpha + 1e-5;
            }
            INFO("wo at " << degrees << " degrees, roughness " << roughness);
            for (int ch = 0; ch < 3; ++ch) CHECK(mean[ch] == Approx(weight[ch]).epsilon(roughness));
            CHECK(near_mirror >= 0.97 * kSamples);
        }
    }
}

TEST_CASE(
    "Veach's smooth plate (copper, alpha 0.01) mirrors a sphere lamp at F(cos) L, by MIS, BSDF and light "
    "sampling alike",
    "[render][ex:ch07.fresnel_conductor]"
    "[ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
    "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cone_solid_angle][ex:ch04.uniform_cone]"
    "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    // The plate of Bitterli's veach-mis scene (pbrt roughness 0.01, not remapped: course r = 0.1; Tungsten's
    // copper) seen at cos θ = 4 / √17 from (0, 4, 1), its mirror direction pointing at the centre of a lamp
    // sphere 0.37 rad in radius: only 0.3 % of the facets (GGX: α² / (α² + tan² θ_m), tan θ_m = 0.19) turn
    // the reflection off the lamp, so every pixel is F(cos θ) L within 1 %. (Tungsten's reference shows
    // 0.3 F L there, for a reason tests/tools/bitterli_check.py gives: the course must not.)
    const Scene scene = scene_from(R"({
      "image": {"width": 4, "height": 4},
      "camera": {"from": [0, 4, 1], "at": [0, 0, 0], "vfov": 1},
      "materials": {"plate": {"type": "conductor", "roughness": 0.1, "eta": [0.200438, 0.924033, 1.102212],
                              "k": [3.912949, 2.452848, 2.142188]},
                    "lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [30, 30, 30]}},
      "shapes": [{"type": "quad", "origin": [-1, 0, 1], "u": [2, 0, 0], "v": [0, 0, -2], "material": "plate"},
                 {"type": "sphere", "center": [0, 8, -2], "radius": 3, "material": "lamp"}]
    })");
    // F(4 / √17) for Tungsten's copper, computed apart from fresnel.cpp (Born and Wolf's closed form).
    const Color expected = 30.0f * Color(0.9521236f, 0.6196616f, 0.5106015f);
    for (const SamplingStrategy strategy :
         {SamplingStrategy::kMis, SamplingStrategy::kBrdf, SamplingStrategy::kLight}) {
        PathOptions options;
        options.strategy = strategy;
        // Light sampling alone finds the narrow lobe in a few of its lamp points: it needs the most paths.
        const int spp = strategy == SamplingStrategy::kLight ? 16384 : 256;
        const Image image =
            render_with(Renderer::kPaths, scene, chapter07_effects(scene), small_settings(4, spp), options)
                .image;
        Color mean(0);
        for (const Color& pixel : image.pixels()) mean += pixel / Real(image.pixels().size());
        INFO(to_string(strategy) << ": " << mean.r << " " << mean.g << " " << mean.b);
        for (int ch = 0; ch < 3; ++ch) {
            CHECK(mean[ch] <= expected[ch] * 1.01f);
            CHECK(mean[ch] >= expected[ch] * 0.985f);
        }
    }
}

TEST_CASE("A conductor is a reflector of the effects, stood in for by its normal colour before chapter 07",
          "[ch07]") {
    const Scene scene = scene_from(R"({
      "camera": {"from": [0, 0, 4], "at": [0, 0, 0]},
      "materials": {"gold": {"type": "conductor", "preset": "gold", "roughness": 0.3},
                    "steel": {"type": "conductor", "eta": [2.9, 2.9, 2.9], "k": [3, 3, 3]}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "gold"},
                 {"type": "sphere", "center": [3, 0, 0], "radius": 1, "material": "steel"}],
      "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
    })");
    CHECK(scene.materials[0].eta == gold().eta);
    CHECK(scene.materials[0].roughness == 0.3f);
    CHECK(scene.materials[1].roughness == 0);
    CHECK(needed(scene).contains(Effect::kReflection));
    CHECK_FALSE(needed(scene).contains(Effect::kRefraction));
    // Chapter 07's table: the conductor itself, rough or smooth.
    const MaterialTable table(scene, EffectSet::all(), refraction_materials());
    const auto* rough = dynamic_cast<const Conductor*>(&table.bsdf(0));
    REQUIRE(rough);
    CHECK_FALSE(rough->flags().delta);
    REQUIRE(dynamic_cast<const Conductor*>(&table.bsdf(1)));
    CHECK(table.bsdf(1).flags().delta);
    CHECK(table.notes().empty());
    // Without chapter 07's hooks (chapters 04 to 06): Lambert of the colour at normal incidence, with a note.
    const MaterialTable before(scene, EffectSet::all());
    const auto* stand_in = dynamic_cast<const LambertBrdf*>(&before.bsdf(0));
    REQUIRE(stand_in);
    CHECK(stand_in->albedo == stand_in_albedo(scene.materials[0]));
    REQUIRE(before.notes().size() == 2);
    CHECK(before.notes()[0].find("chapter 07") != std::string::npos);
}

TEST_CASE("A texture feeds a conductor's index: the metal at a hit is the checker's square's",
          "[conductor][ex:ch07.fresnel_conductor][texture]") {
    const Scene scene = parse_scene(R"({
      "camera": {"from": [0, 0, 4], "at": [0, 0, 0]},
      "materials": {"tiles": {"type": "conductor", "roughness": 0.3, "k": [3, 3, 3],
                              "eta": {"checker": {"even": [0.2, 0.4, 1.5], "odd": [2.9, 2.9, 2.9]}}}},
      "shapes": [{"type": "quad", "origin": [-1, -1, 0], "u": [2, 0, 0], "v": [0, 2, 0], "material": "tiles"}],
      "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
    })",
                                    "tiles.json");
    const Material& tiles = scene.materials[0];
    CHECK(tiles.eta ==
          (Color(0.2f, 0.4f, 1.5f) + Color(2.9f)) / Real(2));  // the mean, for chapters without it
    const MaterialTable table(scene, EffectSet::all(), refraction_materials());
    const Vec3 n(0, 0, 1), wo = glm::normalize(Vec3(0.3f, 0.1f, 1)),
                           wi = glm::normalize(Vec3(-0.2f, 0.4f, 1));
    BsdfAtHit at;
    Hit hit;
    hit.material = 0;
    for (const auto& [uv, eta] :
         {std::pair{Vec2(0.5f, 0.5f), Color(0.2f, 0.4f, 1.5f)}, {Vec2(1.5f, 0.5f), Color(2.9f)}}) {
        hit.uv = uv;
        const auto* metal = dynamic_cast<const Conductor*>(&table.bsdf(hit, at));
        REQUIRE(metal);
        CHECK(metal->eta == eta);
        CHECK(metal->eval(wo, wi, n) == Conductor(eta, Color(3), 0.3f).eval(wo, wi, n));
    }
    // Before chapter 07, its Lambert stand-in takes the colour at normal incidence of the square's metal.
    const MaterialTable before(scene, EffectSet::all());
    hit.uv = {0.5f, 0.5f};
    Material even = tiles;
    even.eta = Color(0.2f, 0.4f, 1.5f);
    CHECK(dynamic_cast<const LambertBrdf&>(before.bsdf(hit, at)).albedo == stand_in_albedo(even));
}

TEST_CASE("The renderer and the path parts are named by their names_of tables", "[names]") {
    CHECK(all_names<Renderer>() ==
          std::vector<std::string>{"direct (chapter 04)", "paths (chapter 06's loop, chapter 07's BSDFs)"});
    CHECK(all_names<PathPart>() == std::vector<std::string>{"seen", "next event", "BSDF hit", "caustic"});
    CHECK(to_string(PathPart::kBsdfHit) == "BSDF hit");
}

// ---------------------------------------------------------------------------------------------------------
// Coated diffuse: a clear coat over a Lambert base

TEST_CASE("The closed-form average Fresnel reflectance from outside is the quadrature of fresnel_dielectric",
          "[ch07][ex:ch07.fresnel_exact]") {
    CHECK(average_fresnel_outside(1) == 0);
    CHECK(average_fresnel_inside(1) == 0);
    for (double eta : {1.01, 1.33, 1.5, 2.0, 3.0}) {
        // 2 ∫ F(c) c dc by the midpoint rule on 20000 steps.
        constexpr int kSteps = 20000;
        double sum = 0;
        for (int i = 0; i < kSteps; ++i) {
            const double c = (i + 0.5) / kSteps;
            sum += 2 * c * double(fresnel_dielectric(Real(c), Real(eta))) / kSteps;
        }
        INFO("eta " << eta);
        CHECK(double(average_fresnel_outside(Real(eta))) == Approx(sum).margin(2e-6));
    }
    // From inside, everything beyond the critical angle reflects: 0.596 for glass (η = 1.5).
    CHECK(double(average_fresnel_inside(Real(kEta))) == Approx(0.5963458).margin(1e-5));
}

TEST_CASE(
    "White furnace of coated diffuse: a white base under a clear coat reflects everything at every angle, by "
    "quadrature and by sampling",
    "[ch07][statistical][ex:ch04.cosine_hemisphere][ex:ch07.fresnel_exact]") {
    std::uint64_t seed = 3500;
    for (double eta : {1.0, 1.33, 1.5, 2.5}) {
        const CoatedDiffuse coat(Color(1), Real(eta));
        for (double degrees : {0.0, 30.0, 60.0, 85.0}) {
            INFO("eta " << eta << ", wo at " << degrees << " degrees");
            const Vec3 wo = direction_at(deg(degrees));
            const double coat_part = double(fresnel_dielectric(wo.z, Real(eta)));
            CHECK(coat_part + albedo_by_quadrature(coat, wo, kUp) == Approx(1).margin(2e-4));
            const Albedo a = albedo_of(coat, wo, kUp, 200000, ++seed);
            CHECK(std::abs(a.mean - 1) <= 5 * a.error + 1e-6);
        }
    }
    // A grey base returns its own albedo through the coat's inner reflections: at ρ = 0.5 and η = 1.5,
    // F + T ρ (1 − F̄_int) / (1 − ρ F̄_int) at normal incidence.
    const CoatedDiffuse grey(Color(0.5f), Real(kEta));
    const double F = 0.04, inside = double(average_fresnel_inside(Real(kEta)));
    const double expected = F + (1 - F) * 0.5 * (1 - inside) / (1 - 0.5 * inside);
    CHECK(double(grey.base_share) == Approx(0.5 * (1 - inside) / (1 - 0.5 * inside)).epsilon(1e-6));
    CHECK(F + albedo_by_quadrature(grey, kUp, kUp) == Approx(expected).margin(2e-4));
}

TEST_CASE(
    "Coated diffuse: sample() fits pdf() by chi-square for wo at 0, 45 and 80 degrees, its coat's delta "
    "samples as many as the pdf leaves out",
    "[statistical][ex:ch04.cosine_hemisphere][ex:ch07.fresnel_exact]") {
    const CoatedDiffuse coat(Color(0.7f, 0.5f, 0.3f), Real(kEta));
    std::uint64_t seed = 3600;
    for (double degrees : {0.0, 45.0, 80.0}) {
        INFO("wo at " << degrees << " degrees");
        const Vec3 wo = outgoing_at(deg(degrees));
        ++seed;
        const DirectionSampler sampler = [&coat, wo](Vec2 u) {
            const BsdfSample s = coat.sample(wo, kSide, u, 0);
            return Drawn{s.wi, double(s.pdf), s.delta};
        };
        const ChiSquare r = test_directions(
            sampler, [&](const Vec3& wi) { return double(coat.pdf(wo, wi, kSide)); }, seed);
        require_fit_with_losses(r, kAlphaPerTest);
    }
}

TEST_CASE("Coated diffuse is reciprocal, and a sample's f and pdf are eval()'s and pdf()'s (or its coat's)",
          "[ch07][ex:ch04.cosine_hemisphere][ex:ch07.fresnel_exact]") {
    Pcg32 rng(3700, 1);
    int coat_samples = 0, base_samples = 0;
    for (int k = 0; k < 20000; ++k) {
        const Color rho(rng.next_real(), rng.next_real(), rng.next_real());
        const CoatedDiffuse coat(rho, 1 + 2 * rng.next_real());
        const Vec3 n = random_unit(rng);
        Vec3 wo = random_unit(rng), wi = random_unit(rng);
        if (glm::dot(wo, n) < 0) wo = -wo;
        if (glm::dot(wi, n) < 0) wi = -wi;
        CHECK(coat.eval(wo, wi, n) == coat.eval(wi, wo, n));
        const BsdfSample s = coat.sample(wo, n, rng.next_vec2(), 0);
        if (!(s.pdf > 0)) continue;
        if (s.delta) {
            ++coat_samples;
            CHECK(glm::dot(s.wi, n) == Approx(glm::dot(wo, n)).margin(1e-5));
            continue;
        }
        ++base_samples;
        CHECK(s.f == coat.eval(wo, s.wi, n));
        CHECK(s.pdf == coat.pdf(wo, s.wi, n));
    }
    CHECK(coat_samples > 500);
    CHECK(base_samples > 5000);
}

TEST_CASE(
    "Furnace: a sphere of white coated diffuse under a uniform sky of radiance 1 renders as 1, its coat's "
    "reflections counted once",
    "[furnace][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable]"
    "[ex:ch03.robust_offset][ex:ch04.cosine_hemisphere][ex:ch05.termination][ex:ch06.mis_weight]"
    "[ex:ch06.path_tracer][ex:ch07.fresnel_exact]") {
    const Scene scene = scene_from(R"({
      "camera": {"from": [0, 0, 4], "at": [0, 0, 0], "up": [0, 1, 0], "vfov": 35},
      "materials": {"plastic": {"type": "coateddiffuse", "albedo": [1, 1, 1], "ior": 1.5}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "plastic"}],
      "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
    })");
    RenderSettings settings = small_settings(24, 256);
    const RenderResult r = render_scene(scene, settings);
    double sum = 0, sum2 = 0;
    const int n = 24 * 24;
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 24; ++x) {
            const double v = double(r.image.at(x, y).g);
            sum += v;
            sum2 += v * v;
        }
    }
    const double mean = sum / n, error = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
    INFO("mean " << mean << ", standard error " << error);
    CHECK(std::abs(mean - 1) <= 5 * error + 1e-4);
    CHECK(r.rays[RayKind::kShadow] > 0);  // the base takes light samples
}

TEST_CASE(
    "A small lamp's reflection in coated diffuse counts in full: with and without next-event estimation the "
    "image is the same",
    "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
    "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cone_solid_angle][ex:ch04.uniform_cone]"
    "[ex:ch04.uniform_cone_pdf][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]"
    "[ex:ch07.fresnel_exact]") {
    // A black base: the floor shows only its coat's reflection of the lamp (out of the picture itself). The
    // reflection is a delta sample: light sampling cannot find it, so MIS must give it the full weight.
    const Scene scene = scene_from(R"({
      "camera": {"from": [0, 1, 3], "at": [0, 0, 0], "up": [0, 1, 0], "vfov": 40},
      "materials": {"plastic": {"type": "coateddiffuse", "albedo": [0, 0, 0], "ior": 1.5},
                    "lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [50, 50, 50]}},
      "shapes": [
        {"type": "quad", "origin": [-2, 0, 2], "u": [4, 0, 0], "v": [0, 0, -4], "material": "plastic"},
        {"type": "sphere", "center": [0, 1.5, -3], "radius": 0.2, "material": "lamp"}
      ]
    })");
    RenderSettings settings = small_settings(24, 64);
    PathOptions nee, hits;
    hits.strategy = SamplingStrategy::kBrdf;
    const RenderResult a = render_with(Renderer::kPaths, scene, chapter07_effects(scene), settings, nee);
    settings.seed = 8;
    const RenderResult b = render_with(Renderer::kPaths, scene, chapter07_effects(scene), settings, hits);
    CHECK(b.image.mean() > 0.01);
    CHECK(b.image.mean() == Approx(a.image.mean()).epsilon(0.03));
}
