// Chapter 06: Monte Carlo with importance sampling. Every sampling routine against its pdf ([statistical]:
// chi-square goodness of fit, about 10^6 samples each, fixed seeds), the pdfs themselves (integrate to 1,
// returned = evaluated, positive at the ends of [0, 1)), the orthonormal basis and the MIS weights at their
// hard cases ([stability]), the irradiance integral estimated each way against its closed forms, and the path
// tracer: the white furnace, every strategy converging to the same image, ray counts and determinism.
#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/triangle.hpp"
#include "04_direct_lighting/area_light_sampling.hpp"
#include "04_direct_lighting/brdf.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/light_picker.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "04_direct_lighting/sphere_light_sampling.hpp"
#include "05_recursive_gi/gi_render.hpp"
#include "06_monte_carlo/distribution_1d.hpp"
#include "06_monte_carlo/distribution_2d.hpp"
#include "06_monte_carlo/environment.hpp"
#include "06_monte_carlo/frisvad_frame.hpp"
#include "06_monte_carlo/lat_long_map.hpp"
#include "06_monte_carlo/irradiance_estimators.hpp"
#include "06_monte_carlo/mis.hpp"
#include "06_monte_carlo/owen_sobol.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "06_monte_carlo/warp_pdfs.hpp"
#include "rt/io/effects.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/core/errors.hpp"
#include "rt/core/random.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"
#include "support/block_means.hpp"
#include "support/chi_square.hpp"
#include "support/closed_box_scene.hpp"
#include "support/direction_warps.hpp"

using namespace rt;
using namespace rt::test;

namespace {

// ---------------------------------------------------------------------------------------------------------
// The chi-square test

// Every chi-square test of this file (the uniform sphere 1, BRDF samplers 25, Sobol points 5, the environment
// image 2), each run at
// the Šidák-corrected level of tests/support/chi_square.hpp. Chapter 04's warps are tested by chapter 04's
// tests.
constexpr int kChiSquareTests = 33;
constexpr double kAlpha = 0.01;
const double kAlphaPerTest = sidak_level(kChiSquareTests, kAlpha);
constexpr int kSamples = kDirectionSamples;

// A unit direction at polar angle θ from +z, turned by φ about z.
Vec3 polar(double theta, double phi = 0) {
    return Vec3(Real(std::sin(theta) * std::cos(phi)), Real(std::sin(theta) * std::sin(phi)),
                Real(std::cos(theta)));
}

const Vec3 kUp{0, 0, 1};

// The five outgoing directions of the BRDF tests: 0°, 30°, 60°, 80° and 89° from the normal.
std::vector<Vec3> five_outgoing() {
    std::vector<Vec3> wo;
    for (double degrees : {0.0, 30.0, 60.0, 80.0, 89.0})
        wo.push_back(polar(degrees * std::numbers::pi / 180, 0.4));
    return wo;
}

// The BRDFs whose samplers are tested: Lambert, and the two lobes at roughness 0.2 and 0.5 (e = 48 and 6).
std::vector<std::pair<std::string, std::shared_ptr<const Bsdf>>> sampled_brdfs() {
    return {{"lambert", std::make_shared<LambertBrdf>(Color(0.7f))},
            {"glossy 0.2", std::make_shared<GlossyBrdf>(Color(0.7f), phong_exponent(0.2f))},
            {"glossy 0.5", std::make_shared<GlossyBrdf>(Color(0.7f), phong_exponent(0.5f))},
            {"retro 0.2", std::make_shared<RetroreflectiveBrdf>(Color(0.7f), phong_exponent(0.2f))},
            {"retro 0.5", std::make_shared<RetroreflectiveBrdf>(Color(0.7f), phong_exponent(0.5f))}};
}

Warp uniform_sphere_warp() {
    return bare("uniform sphere", sample_uniform_sphere,
                [](const Vec3&) { return double(kUniformSpherePdf); });
}

// Every warp under test, in the order of its seed (101, 102, …; see require_warps_fit).
std::vector<Warp> warps() {
    std::vector<Warp> w{uniform_hemisphere_warp(), cosine_hemisphere_warp(), uniform_sphere_warp()};
    for (const auto& group :
         {cone_warps(), power_cosine_warps(), light_warps(), solid_angle_quad_warps()}) {
        w.insert(w.end(), group.begin(), group.end());
    }
    return w;
}

// The chi-square test of each warp against its pdf at this file's level, with seeds first_seed, … (each warp
// its own, as numbered in warps()).
void require_warps_fit(const std::vector<Warp>& group, std::uint64_t first_seed) {
    require_warps_fit(group, first_seed, kAlphaPerTest);
}

Vec3 random_unit(Pcg32& rng) {
    return sample_uniform_sphere(rng.next_vec2());
}

// A scene for the furnace: a diffuse sphere of the given albedo under a uniform environment of radiance 1.
Scene furnace_scene(Real albedo) {
    Scene scene;
    scene.file = "furnace";
    scene.camera = CameraDesc{{0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 40};
    Material m;
    m.name = "diffuse";
    m.albedo = Color(albedo);
    scene.materials.push_back(m);
    scene.shapes.push_back(Shape{SphereShape{{0, 0, 0}, 1}, 0, "shapes[0]"});
    scene.environment = EnvironmentLight{Color(1)};
    return scene;
}

// Whether pixel (x, y) lies wholly on the unit sphere at the origin: its four corners' rays hit it.
bool wholly_on_unit_sphere(const PinholeCamera& camera, int x, int y) {
    bool inside = true;
    for (Real dx : {0.0f, 1.0f})
        for (Real dy : {0.0f, 1.0f}) {
            const Ray r = camera_ray(camera, Real(x) + dx, Real(y) + dy);
            const Real b = glm::dot(r.origin, r.direction);
            inside = inside && (b * b - (glm::dot(r.origin, r.origin) - 1) > 0);
        }
    return inside;
}

RenderResult render_scene(const Scene& scene, SamplingStrategy strategy, int size, int spp,
                          std::uint64_t seed, int threads = 1,
                          const TerminationSettings& termination = PathOptions{}.termination) {
    // What a run of chapter 06 simulates for the scene, as for a user's scene file.
    const EffectSet simulated = simulated_effects(scene, kRecursiveChapterEffects);
    const RenderScene prepared(scene, simulated);
    PathOptions options;
    options.simulated = simulated;
    options.strategy = strategy;
    options.termination = termination;
    const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
    const RenderSettings settings{size, size, spp, seed, threads, ProgressStyle::kNone};
    return render_paths(tracer, camera, settings);
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// The chi-square test itself

TEST_CASE("The chi-square p-value matches known quantiles, and the test rejects a wrong pdf",
          "[statistical][ex:ch04.uniform_hemisphere]"
          "[ex:ch06.uniform_sphere]") {
    // χ² quantiles: P(χ²₁ >= 6.635) = 0.01, P(χ²₁₀ >= 23.209) = 0.01, P(χ²₁₀₀ >= 124.342) = 0.05.
    CHECK(chi_square_p_value(6.635, 1) == Approx(0.01).epsilon(1e-3));
    CHECK(chi_square_p_value(23.209, 10) == Approx(0.01).epsilon(1e-3));
    CHECK(chi_square_p_value(124.342, 100) == Approx(0.05).epsilon(1e-3));
    CHECK(chi_square_p_value(2.0, 2) == Approx(std::exp(-1.0)).epsilon(1e-9));
    // Uniform hemisphere directions against the cosine pdf: rejected outright.
    const ChiSquare wrong = test_directions(
        [](Vec2 u) {
            return Drawn{sample_uniform_hemisphere(u), 0};
        },
        [](const Vec3& d) { return double(cosine_hemisphere_pdf(d.z)); }, 1);
    CHECK(wrong.p_value < 1e-12);
    // A pdf that is 0 where samples land counts them as bad.
    const ChiSquare zero = test_directions(
        [](Vec2 u) {
            return Drawn{sample_uniform_sphere(u), 0};
        },
        [](const Vec3& d) { return double(cosine_hemisphere_pdf(d.z)); }, 2);
    CHECK(zero.bad_samples > kSamples / 3);
}

// ---------------------------------------------------------------------------------------------------------
// Sampling routines against their pdfs

TEST_CASE("Uniform sphere directions fit the pdf 1 / (4 pi)", "[statistical][ex:ch06.uniform_sphere]") {
    require_warps_fit({uniform_sphere_warp()}, 103);
}

TEST_CASE(
    "Every BRDF sampler passes the chi-square test for 5 outgoing directions up to 89 degrees, its pdf "
    "integrates to 1, to at most 1 above the surface",
    "[statistical][ex:ch04.cosine_hemisphere][ex:ch04.glossy][ex:ch04.lambert][ex:ch04.power_cosine]"
    "[ex:ch04.power_cosine_pdf]") {
    std::uint64_t seed = 200;
    for (const auto& [name, owner] : sampled_brdfs()) {
        const Bsdf& brdf = *owner;
        for (const Vec3& wo : five_outgoing()) {
            INFO(name << ", wo.z = " << wo.z);
            const Bsdf& b = brdf;
            // The lobes are sampled whole: a direction below the surface carries f = 0 (the light the lobe
            // loses), so over the sphere the pdf integrates to 1 and over the upper hemisphere to at most 1.
            const ChiSquare r = test_directions(
                [&](Vec2 u) {
                    const BsdfSample s = sample(b, wo, kUp, u);
                    return Drawn{s.wi, double(s.pdf)};
                },
                [&](const Vec3& wi) { return double(pdf(b, wo, wi, kUp)); }, ++seed);
            require_fit(r, kAlphaPerTest);
            CHECK(r.expected_upper / kSamples <= 1 + 1e-3);
        }
    }
}

TEST_CASE("Points sampled on a triangle lie in its plane, and a quad's point is its origin plus u and v",
          "[ex:ch04.uniform_triangle]") {
    // (The barycentrics themselves are fitted by chapter 04's tests.)
    Pcg32 rng(300, 2);
    const Vec3 p0{1, 2, 3}, p1{4, 2, 3}, p2{1, 6, 5};
    for (int s = 0; s < 1000; ++s) {
        const Vec3 x = sample_triangle_point(p0, p1, p2, rng.next_vec2());
        CHECK(std::abs(glm::dot(x - p0, glm::normalize(glm::cross(p1 - p0, p2 - p0)))) < 1e-5f);
    }
    const Vec3 q = sample_quad_point({1, 1, 1}, {2, 0, 0}, {0, 3, 0}, Vec2(0.5f, 0.25f));
    CHECK(q == Vec3(2, 1.75f, 1));
}

TEST_CASE("The pdf returned with a sample equals the pdf evaluated for its direction",
          "[statistical][ex:ch02.quad_packet][ex:ch02.sphere_stable][ex:ch04.cone_solid_angle]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.glossy][ex:ch04.lambert][ex:ch04.power_cosine]"
          "[ex:ch04.power_cosine_pdf][ex:ch04.retroreflective][ex:ch04.sample_quad_light]"
          "[ex:ch04.uniform_cone]") {
    Pcg32 rng(400, 1);
    for (const auto& [name, owner] : sampled_brdfs()) {
        const Bsdf& brdf = *owner;
        for (const Vec3& wo : five_outgoing()) {
            INFO(name << ", wo.z = " << wo.z);
            for (int s = 0; s < 2000; ++s) {
                const BsdfSample bs = sample(brdf, wo, kUp, rng.next_vec2());
                REQUIRE(bs.pdf == Approx(pdf(brdf, wo, bs.wi, kUp)).epsilon(1e-5));
                REQUIRE(bs.f == eval(brdf, wo, bs.wi, kUp));
            }
        }
    }
    // Light samples: quad, sphere, and the picker's pdf through a real hit on the Cornell box's lamp.
    const QuadLight quad = make_quad_light({-1, -0.5f, 0.5f}, {0, 1.5f, 0}, {2, 0, 0}, Color(1));
    const SphereLight sphere{{0.3f, 0.4f, 1.2f}, 0.6f, Color(1)};
    for (int s = 0; s < 2000; ++s) {
        const auto q = sample_quad_light(quad, Vec3(0), rng.next_vec2());
        REQUIRE(q);
        CHECK(q->pdf == Approx(quad_light_pdf(quad, Vec3(0), q->wi)).epsilon(1e-3));
        const auto c = sample_sphere_light(sphere, Vec3(0), rng.next_vec2());
        REQUIRE(c);
        CHECK(c->pdf == Approx(sphere_light_pdf(sphere, Vec3(0))).epsilon(1e-6));
    }
    const Scene cornell = load_scene(scene_path("ch06_default.json"));
    const World world(cornell);
    const LightPicker picker(collect_lights(cornell));
    REQUIRE_FALSE(picker.empty());
    const Vec3 p{450, 10, 150};  // on the floor, in front of the box, beside the sphere
    int checked = 0;
    for (int s = 0; s < 2000; ++s) {
        const auto ls = picker.sample(p, rng.next_real(), rng.next_vec2());
        REQUIRE(ls);
        const auto hit = world.intersect(Ray{p, ls->wi});
        REQUIRE(hit);
        if (hit->light < 0) continue;  // blocked by the box
        CHECK(picker.pdf(p, ls->wi, *hit) == Approx(ls->pdf).epsilon(1e-3));
        ++checked;
    }
    CHECK(checked > 1000);
}

TEST_CASE("Lambert: f cos / pdf equals the albedo for every sample",
          "[statistical][ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch06.uniform_sphere]") {
    const Color albedo{0.2f, 0.5f, 0.9f};
    const LambertBrdf lambert{albedo};
    Pcg32 rng(500, 1);
    for (int s = 0; s < 100000; ++s) {
        const Vec3 n = random_unit(rng);
        Vec3 wo = random_unit(rng);
        if (glm::dot(wo, n) < 0) wo = -wo;
        const BsdfSample bs = sample(lambert, wo, n, rng.next_vec2());
        const Real cos_i = glm::dot(bs.wi, n);
        if (!(cos_i > 0)) continue;  // a direction rounded onto the horizon carries nothing
        const Color weight = bs.f * cos_i / bs.pdf;
        REQUIRE(weight.r == Approx(albedo.r).epsilon(1e-5));
        REQUIRE(weight.g == Approx(albedo.g).epsilon(1e-5));
        REQUIRE(weight.b == Approx(albedo.b).epsilon(1e-5));
    }
}

TEST_CASE(
    "Random numbers 0, 0.5 and the largest float below 1 give finite unit directions and a positive pdf",
    "[stability][ex:ch04.cone_solid_angle][ex:ch04.cosine_hemisphere][ex:ch04.glossy]"
    "[ex:ch04.lambert][ex:ch04.power_cosine][ex:ch04.sample_quad_light][ex:ch04.uniform_cone]"
    "[ex:ch04.uniform_hemisphere][ex:ch04.uniform_triangle]"
    "[ex:ch04.power_cosine_pdf][ex:ch04.uniform_cone_pdf][ex:ch04.uniform_hemisphere_pdf]"
    "[ex:ch06.uniform_sphere]") {
    const Real ends[] = {0, 0.5f, kOneMinusEpsilon};
    for (const Warp& w : warps()) {
        for (Real a : ends) {
            for (Real b : ends) {
                INFO(w.name << " at u = (" << a << ", " << b << ")");
                const Drawn d = w.sample(Vec2(a, b));
                CHECK(is_finite(d.w));
                CHECK(glm::length(d.w) == Approx(1).epsilon(1e-5));
                CHECK(d.pdf > 0);
                CHECK(std::isfinite(d.pdf));
                CHECK(w.pdf(d.w) > 0);
            }
        }
    }
    for (const auto& [name, owner] : sampled_brdfs()) {
        const Bsdf& brdf = *owner;
        for (const Vec3& wo : five_outgoing()) {
            for (Real a : ends) {
                for (Real b : ends) {
                    INFO(name << ", wo.z = " << wo.z << " at u = (" << a << ", " << b << ")");
                    const BsdfSample s = sample(brdf, wo, kUp, Vec2(a, b));
                    CHECK(is_finite(s.wi));
                    CHECK(glm::length(s.wi) == Approx(1).epsilon(1e-5));
                    CHECK(s.pdf > 0);
                    CHECK(std::isfinite(s.pdf));
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------------------
// The orthonormal basis

namespace {

// The largest departure from orthonormality: | |t|² − 1 |, | |b|² − 1 |, |t·b|, |t·n|, |b·n| (in double).
double frame_error(const Frame& f) {
    const Vec3d t(f.t), b(f.b), n(f.n);
    return std::max({std::abs(glm::dot(t, t) - 1), std::abs(glm::dot(b, b) - 1), std::abs(glm::dot(t, b)),
                     std::abs(glm::dot(t, n)), std::abs(glm::dot(b, n))});
}

// The float normal at z = cos θ and azimuth φ, from double.
Vec3 normal_at(double z, double phi) {
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    return Vec3(Real(r * std::cos(phi)), Real(r * std::sin(phi)), Real(z));
}

}  // namespace

TEST_CASE("The orthonormal basis is orthonormal to 1e-6 for the axes, random normals and z near -1",
          "[stability][ex:ch06.uniform_sphere]") {
    for (const Vec3& n :
         {Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, -1, 0}, Vec3{0, 0, 1}, Vec3{0, 0, -1}}) {
        INFO(n.x << " " << n.y << " " << n.z);
        const Frame f = make_frame(n);
        CHECK(frame_error(f) <= 1e-6);
        CHECK(glm::dot(glm::cross(f.t, f.b), f.n) > 0.999f);  // right-handed
    }
    Pcg32 rng(600, 1);
    double worst = 0;
    for (int i = 0; i < 1000000; ++i) worst = std::max(worst, frame_error(make_frame(random_unit(rng))));
    CHECK(worst <= 1e-6);
    // z = −1 + k 2^-24 for k = 0 … 4095: every float from −1 up to −0.99976, each at 16 azimuths.
    constexpr int kSteps = 4096;
    double worst_duff = 0, worst_frisvad = 0;
    for (int k = 0; k < kSteps; ++k) {
        const double z = -1 + std::ldexp(double(k), -24);
        for (int a = 0; a < 16; ++a) {
            const Vec3 n = normal_at(z, 0.1 + a * std::numbers::pi / 8);
            worst_duff = std::max(worst_duff, frame_error(make_frame(n)));
            worst_frisvad = std::max(worst_frisvad, frame_error(make_frame_frisvad(n)));
        }
    }
    INFO("worst error: Duff et al. " << worst_duff << ", Frisvad " << worst_frisvad);
    CHECK(worst_duff <= 1e-6);
    // The naive basis (Frisvad 2012) is not: more than 100 times the 1e-6 asked, as 1 + n_z has lost its
    // digits.
    CHECK(worst_frisvad > 1e-4);
}

// ---------------------------------------------------------------------------------------------------------
// MIS weights

TEST_CASE("MIS weights sum to 1 and stay finite when a pdf is 0, tiny, huge or infinite",
          "[stability][ex:ch06.mis_weight]") {
    const Real inf = kInfinity;
    const std::vector<Real> pdfs{
        0, 1e-30f, 1e-20f, 0.5f, 1, 3, 1e20f, 1e30f, std::numeric_limits<Real>::max(), inf};
    for (Real a : pdfs) {
        for (Real b : pdfs) {
            INFO("p_a = " << a << ", p_b = " << b);
            for (int beta : {1, 2}) {
                const Real wa = mis_weight(1, a, 1, b, beta), wb = mis_weight(1, b, 1, a, beta);
                CHECK(std::isfinite(wa));
                CHECK(wa >= 0);
                CHECK(wa <= 1);
                CHECK(wa + wb == Approx(1).margin(1e-6));
            }
        }
    }
    CHECK(power_heuristic(inf, 1) == 1);
    CHECK(power_heuristic(0, 1) == 0);
    CHECK(power_heuristic(1, 0) == 1);
    CHECK(power_heuristic(3, 1) == Approx(0.9));
    CHECK(balance_heuristic(3, 1) == Approx(0.75));
    // Sample counts: n_a p_a against n_b p_b.
    CHECK(mis_weight(4, 1, 1, 2, 2) == Approx(0.8));
}

// ---------------------------------------------------------------------------------------------------------
// The irradiance integral each way

TEST_CASE("Every strategy estimates the irradiance of a quad, a sphere and the sky without bias",
          "[statistical][ex:ch01.pixel_sample][ex:ch04.cone_solid_angle][ex:ch04.cosine_hemisphere]"
          "[ex:ch04.lambert_polygon][ex:ch04.sample_quad_light][ex:ch04.uniform_cone]"
          "[ex:ch04.uniform_hemisphere][ex:ch06.mis_weight]"
          "[ex:ch04.uniform_cone_pdf]") {
    for (const IrradianceCase& c : irradiance_cases()) {
        for (SamplingStrategy s : kAllStrategies) {
            for (PointSet points : kAllPointSets) {
                const IrradianceEstimate e = estimate_irradiance(c, s, 100000, 7, points);
                INFO(c.name << ", " << to_string(s) << ", " << to_string(points) << ": " << e.mean << " +- "
                            << e.standard_error << ", exact " << c.exact);
                CHECK(std::abs(e.mean - c.exact) <= 4 * e.standard_error + 1e-6 * c.exact);
            }
        }
    }
    // Importance sampling removes variance: for the sky, cosine sampling is exact (σ = 0); for the small
    // lights, light sampling and MIS beat uniform directions by far.
    const auto cases = irradiance_cases();
    CHECK(estimate_irradiance(cases[2], SamplingStrategy::kCosine, 1000, 1).variance < 1e-10);
    for (int i : {0, 1}) {
        const double uniform =
            estimate_irradiance(cases[std::size_t(i)], SamplingStrategy::kUniform, 100000, 1).variance;
        CHECK(estimate_irradiance(cases[std::size_t(i)], SamplingStrategy::kLight, 100000, 1).variance <
              uniform / 4);
        CHECK(estimate_irradiance(cases[std::size_t(i)], SamplingStrategy::kMis, 100000, 1).variance <
              uniform / 4);
    }
}

namespace {

// The RMSE of the cosine-weighted estimate of the first irradiance case (a quad light) with n points, over
// 200 runs of their own seeds.
double quad_irradiance_rmse(int n, PointSet points) {
    const IrradianceCase quad = irradiance_cases()[0];
    double sum2 = 0;
    constexpr int kRuns = 200;
    for (int r = 0; r < kRuns; ++r) {
        const double e =
            estimate_irradiance(quad, SamplingStrategy::kCosine, n, 1000 + r, points).mean - quad.exact;
        sum2 += e * e;
    }
    return std::sqrt(sum2 / kRuns);
}

}  // namespace

TEST_CASE("Error falls like 1/sqrt(N), and faster with stratified points",
          "[statistical][ex:ch01.pixel_sample][ex:ch04.cosine_hemisphere][ex:ch04.lambert_polygon]") {
    const double r64 = quad_irradiance_rmse(64, PointSet::kIndependent);
    const double r1024 = quad_irradiance_rmse(1024, PointSet::kIndependent);
    // 16× the samples: 4× less error (within the spread of 200 runs).
    CHECK(r64 / r1024 > 3.3);
    CHECK(r64 / r1024 < 4.8);
    // Stratified: less error for the same N.
    CHECK(quad_irradiance_rmse(1024, PointSet::kStratified) < r1024 / 2);
}

// ---------------------------------------------------------------------------------------------------------
// Owen-scrambled Sobol points

namespace {

// Whether each aligned block of 2^m of the points (m = 0 … 12) has one point in each elementary interval of
// area 2^-m, for every shape 2^-k × 2^-(m−k): a (0, 2)-sequence in base 2. The points are 24-bit fractions.
bool is_02_sequence(const std::vector<std::uint32_t>& xs, const std::vector<std::uint32_t>& ys) {
    const int points = int(xs.size());
    for (int m = 0; m <= 12; ++m) {
        const int block = 1 << m;
        for (int first = 0; first + block <= points; first += block) {
            for (int k = 0; k <= m; ++k) {
                std::vector<int> cells(std::size_t(block), 0);
                for (int i = first; i < first + block; ++i) {
                    const std::uint32_t cx = xs[std::size_t(i)] >> (24 - k);
                    const std::uint32_t cy = ys[std::size_t(i)] >> (24 - (m - k));
                    ++cells[std::size_t((cy << k) | cx)];
                }
                if (!std::all_of(cells.begin(), cells.end(), [](int c) { return c == 1; })) return false;
            }
        }
    }
    return true;
}

}  // namespace

TEST_CASE("Sobol points: every pair of dimensions is a (0,2)-sequence in each power-of-two block") {
    // The unscrambled points, and the scrambled and padded ones of any seed.
    constexpr int kPoints = 4096;
    for (std::uint64_t seed : {1ull, 77ull}) {
        for (std::uint32_t pair : {0u, 1u, 5u}) {
            std::vector<std::uint32_t> xs(kPoints), ys(kPoints);
            for (int i = 0; i < kPoints; ++i) {
                xs[std::size_t(i)] = std::uint32_t(owen_sobol(std::uint32_t(i), 2 * pair, seed) * 0x1p24f);
                ys[std::size_t(i)] =
                    std::uint32_t(owen_sobol(std::uint32_t(i), 2 * pair + 1, seed) * 0x1p24f);
            }
            INFO("seed " << seed << ", pair " << pair);
            CHECK(is_02_sequence(xs, ys));
        }
    }
    // Unscrambled: the van der Corput sequence and Sobol's second dimension, 0, 1/2, 1/4 (3/4 for y), …
    CHECK(sobol_bits(1, 0) == 0x80000000u);
    CHECK(sobol_bits(2, 0) == 0x40000000u);
    CHECK(sobol_bits(3, 0) == 0xc0000000u);
    CHECK(sobol_bits(2, 1) == 0xc0000000u);
    CHECK(sobol_bits(3, 1) == 0x40000000u);
    CHECK(reverse_bits(1u) == 0x80000000u);
    // Owen's scramble keeps the digits before a given one together: x's first k digits decide the
    // scrambled value's first k.
    for (std::uint32_t x : {0x12345678u, 0xdeadbeefu}) {
        const std::uint32_t y = x ^ 0x0000ffffu;  // the same first 16 digits
        CHECK(nested_uniform_scramble(x, 99) >> 16u == nested_uniform_scramble(y, 99) >> 16u);
    }
}

TEST_CASE("Sobol points: uniform over pixels, pairs independent within one pixel (chi-square)",
          "[statistical]") {
    constexpr int kCells = 16;  // a 16 x 16 grid
    auto test = [](const char* what, auto&& point, int n) {
        std::vector<double> observed(kCells * kCells, 0),
            expected(kCells * kCells, double(n) / (kCells * kCells));
        for (int i = 0; i < n; ++i) {
            const Vec2 p = point(i);
            REQUIRE(p.x >= 0);
            REQUIRE(p.x < 1);
            REQUIRE(p.y >= 0);
            REQUIRE(p.y < 1);
            observed[std::size_t(int(p.y * kCells) * kCells + int(p.x * kCells))] += 1;
        }
        const ChiSquare c = chi_square(observed, expected);
        INFO(what << ": chi-square " << c.statistic << ", " << c.dof << " dof, p = " << c.p_value);
        CHECK(c.p_value > kAlphaPerTest);
    };
    // One sample of each of 100000 pixels: pair j of dimensions is uniform on [0, 1)² (4 tests).
    for (std::uint32_t pair = 0; pair < 4; ++pair) {
        test(
            "pixels' first sample",
            [&](int i) {
                OwenSobolStream stream(std::uint64_t(i), 0, 3);
                for (std::uint32_t d = 0; d < pair; ++d) stream.next_vec2();
                return stream.next_vec2();
            },
            100000);
    }
    // 65536 samples of one pixel: a 1D draw and the next draw's first coordinate come from different pairs,
    // whose shuffles make them independent; were they not shuffled, a pixel's points would lie on a few
    // lines (1 test).
    test(
        "a 1D draw and the next draw of one pixel",
        [&](int i) {
            OwenSobolStream stream(42, std::uint32_t(i), 3);
            const Real first = stream.next_real();
            return Vec2(first, stream.next_vec2().x);
        },
        65536);
}

TEST_CASE("Sobol points: each draw of a sample's stream is a (0,2)-sequence, after 1D draws too") {
    // The path loop draws 1D numbers (which light, roulette) between its 2D ones (a point on a light, a
    // direction). A 2D draw whose two coordinates came from two different pairs of dimensions would be
    // stratified along each axis only, not in the square: each draw takes a pair of its own.
    constexpr int kPoints = 4096;
    std::vector<std::uint32_t> xs(kPoints), ys(kPoints), xs2(kPoints), ys2(kPoints);
    for (int i = 0; i < kPoints; ++i) {
        OwenSobolStream stream(9, std::uint32_t(i), 4);
        stream.next_vec2();  // the camera ray's point in the pixel
        stream.next_real();  // which light
        const Vec2 light = stream.next_vec2();
        stream.next_real();  // roulette
        const Vec2 direction = stream.next_vec2();
        xs[std::size_t(i)] = std::uint32_t(light.x * 0x1p24f);
        ys[std::size_t(i)] = std::uint32_t(light.y * 0x1p24f);
        xs2[std::size_t(i)] = std::uint32_t(direction.x * 0x1p24f);
        ys2[std::size_t(i)] = std::uint32_t(direction.y * 0x1p24f);
    }
    CHECK(is_02_sequence(xs, ys));
    CHECK(is_02_sequence(xs2, ys2));
}

TEST_CASE("Sobol points: the fast pair is the definitions' composition, bit for bit") {
    // owen_sobol_pair cancels reversals and reads Sobol's second dimension bit-reversed; the numbers are
    // those of the definitions: shuffle the index, take the two Sobol dimensions, scramble each.
    for (std::uint64_t seed : {3ull, 0xdeadbeefcafeull}) {
        for (std::uint32_t pair : {0u, 1u, 7u}) {
            for (std::uint32_t index : {0u, 1u, 2u, 3u, 63u, 64u, 1000u, 123456u, 0xffffffffu}) {
                Pcg32 seeds(seed, pair);
                const std::uint32_t shuffled = nested_uniform_scramble(index, seeds.next_uint());
                const std::uint32_t x = nested_uniform_scramble(sobol_bits(shuffled, 0), seeds.next_uint());
                const std::uint32_t y = nested_uniform_scramble(sobol_bits(shuffled, 1), seeds.next_uint());
                const Vec2 p = owen_sobol_pair(index, pair, seed);
                CHECK(p.x == Real(x >> 8u) * Real(0x1.0p-24));
                CHECK(p.y == Real(y >> 8u) * Real(0x1.0p-24));
                CHECK(owen_sobol(index, 2 * pair, seed) == p.x);
                CHECK(owen_sobol(index, 2 * pair + 1, seed) == p.y);
            }
        }
    }
}

TEST_CASE("Sobol points are a pure function of (pixel, sample, dimension, seed)") {
    // What makes an image independent of the thread count: no state is shared between samples.
    OwenSobolStream a(7, 12, 5), b(7, 12, 5), other_pixel(8, 12, 5), other_seed(7, 12, 6);
    std::vector<Real> first;
    for (int d = 0; d < 64; ++d) first.push_back(a.next_real());
    int same_pixel = 0, same_seed = 0;
    for (int d = 0; d < 64; ++d) {
        CHECK(b.next_real() == first[std::size_t(d)]);
        same_pixel += other_pixel.next_real() == first[std::size_t(d)] ? 1 : 0;
        same_seed += other_seed.next_real() == first[std::size_t(d)] ? 1 : 0;
    }
    CHECK(same_pixel < 2);
    CHECK(same_seed < 2);
}

TEST_CASE("Sobol points: the irradiance error falls faster than 1/sqrt(N)",
          "[statistical][ex:ch01.pixel_sample][ex:ch04.cosine_hemisphere][ex:ch04.lambert_polygon]") {
    const double s64 = quad_irradiance_rmse(64, PointSet::kSobol);
    const double s1024 = quad_irradiance_rmse(1024, PointSet::kSobol);
    INFO("Sobol RMSE " << s64 << " at N = 64, " << s1024 << " at N = 1024");
    // 16x the samples: 4x less error for independent points, 16^0.75 = 8x for Owen-scrambled Sobol points on
    // an integrand with an edge (the light's outline); measured
    CHECK(s64 / s1024 > 6);
    CHECK(s1024 < quad_irradiance_rmse(1024, PointSet::kStratified));
}

// ---------------------------------------------------------------------------------------------------------
// The path tracer

TEST_CASE(
    "White furnace: a diffuse sphere under uniform light 1 is exactly its albedo times 1 with cosine "
    "sampling",
    "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable]"
    "[ex:ch03.robust_offset][ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch05.termination]"
    "[ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    for (Real albedo : {1.0f, 0.5f}) {
        const Scene scene = furnace_scene(albedo);
        const RenderResult cosine = render_scene(scene, SamplingStrategy::kCosine, 32, 4, 1);
        const RenderResult mis = render_scene(scene, SamplingStrategy::kMis, 32, 4, 1);
        // Pixels on the sphere see ρ·1 (one bounce, every ray escapes a convex sphere), the others see 1.
        const PinholeCamera camera = make_pinhole_camera(scene.camera, 32, 32);
        double worst = 0, sphere_pixels = 0, mis_sum = 0;
        for (int y = 0; y < 32; ++y) {
            for (int x = 0; x < 32; ++x) {
                if (!wholly_on_unit_sphere(camera, x, y)) continue;
                ++sphere_pixels;
                const Color c = cosine.image.at(x, y), m = mis.image.at(x, y);
                worst = std::max({worst, std::abs(double(c.r) - albedo), std::abs(double(c.g) - albedo),
                                  std::abs(double(c.b) - albedo)});
                mis_sum += double(m.g);
            }
        }
        INFO("albedo " << albedo << ": worst pixel off by " << worst << " over " << sphere_pixels
                       << " pixels");
        REQUIRE(sphere_pixels > 200);
        CHECK(worst <= 1e-5);  // zero variance: float rounding only
        CHECK(mis_sum / sphere_pixels == Approx(albedo).epsilon(1e-5));
        CHECK(cosine.rays[RayKind::kShadow] == 0);
    }
}

TEST_CASE(
    "A depth cap of N counts every path of at most N bounces whatever the strategy, the furnace's sum of "
    "rho^k for k from 0 to N",
    "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch03.robust_offset]"
    "[ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
    "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    // Chapter 05's furnace: six walls of albedo 0.8 that each emit 1. A path of k bounces carries 0.8^k.
    // Light sampling counts the light of bounce N by its estimate at vertex N; the BSDF strategy and MIS
    // need the ray drawn there, traced for the light it meets alone.
    const Scene scene = load_scene(scene_path("ch05_furnace.json"));
    for (int cap : {1, 2, 3}) {
        double expected = 0;
        for (int k = 0; k <= cap; ++k) expected += std::pow(0.8, k);
        for (SamplingStrategy strategy :
             {SamplingStrategy::kCosine, SamplingStrategy::kLight, SamplingStrategy::kMis}) {
            const RenderResult r =
                render_scene(scene, strategy, 32, 16, 7, 1, TerminationSettings{Termination::kMaxDepth, cap});
            // The pixels are independent estimates: their spread gives the mean's standard error.
            double sum = 0, squares = 0;
            for (const Color& c : r.image.pixels()) {
                sum += c.g;
                squares += double(c.g) * c.g;
            }
            const double n = double(r.image.pixels().size());
            const double mean = sum / n;
            const double error = std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1));
            INFO("cap " << cap << ", " << to_string(strategy) << ": mean " << mean << " ± " << error
                        << ", expected " << expected);
            // (The cosine strategy has no variance here: float rounding alone, 1e-5.)
            CHECK(std::abs(mean - expected) <= 5 * error + 1e-5 * expected);
        }
    }
}

namespace {

// A vertex that draws its continuation from the uniform hemisphere whatever the BSDF, and gives MIS that
// density (a stand-in for a guided vertex); it counts its draws.
class UniformVertex : public BsdfVertex {
  public:
    UniformVertex(const BsdfVertex& vertex, std::atomic<long>& draws) : BsdfVertex(vertex), draws_(draws) {}
    Real pdf(const Vec3& wi) const {
        return glm::dot(wi, normal()) > 0 ? uniform_hemisphere_pdf(Vec3(0, 0, 1)) : Real(0);
    }
    std::optional<Continuation> sample(SampleStream rng) const {
        ++draws_;
        const Vec3 local = sample_uniform_hemisphere(rng.next_vec2());
        Continuation c;
        c.sample.wi = glm::normalize(make_frame(normal()).to_world(local));
        c.sample.pdf = uniform_hemisphere_pdf(local);
        const Scattering f = toward(c.sample.wi);
        if (f.none()) return std::nullopt;
        c.sample.f = f.f;
        c.cos_i = f.cos;
        return c;
    }

  private:
    std::atomic<long>& draws_;
};

// Chapter 06's paths with that vertex at every surface: an extension that changes one member.
class UniformPaths : public SurfacePaths {
  public:
    UniformPaths(const PathTracer& tracer, std::atomic<long>& draws) : SurfacePaths(tracer), draws_(draws) {}
    UniformVertex vertex(const Hit& hit, const Vec3& wo, const Bsdf& bsdf) const {
        return {SurfacePaths::vertex(hit, wo, bsdf), draws_};
    }

  private:
    std::atomic<long>& draws_;
};

// A tracer render_paths can run: chapter 06's loop with UniformPaths.
struct UniformTracer {
    const PathTracer& tracer;
    std::atomic<long>& draws;
    Color radiance(const Ray& ray, SampleStream rng, RayCounts& rays) const {
        PathState path;
        tracer.trace(ray, path, rng, rays, nullptr, UniformPaths(tracer, draws));
        return path.L;
    }
    const PathOptions& options() const { return tracer.options(); }
};

}  // namespace

TEST_CASE(
    "An extension's vertex draws every continuation and gives MIS its density: a uniform-hemisphere vertex "
    "keeps the white furnace's mean",
    "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable][ex:ch03.robust_offset]"
    "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.uniform_hemisphere][ex:ch04.uniform_hemisphere_pdf]"
    "[ex:ch05.termination][ex:ch06.mis_weight]"
    "[ex:ch06.path_tracer]") {
    const Scene scene = furnace_scene(0.5f);
    const EffectSet simulated = simulated_effects(scene, kRecursiveChapterEffects);
    const RenderScene prepared(scene, simulated);
    PathOptions options;
    options.simulated = simulated;
    const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
    const int size = 32;
    const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
    const RenderSettings settings{size, size, 16, 1, 1, ProgressStyle::kNone};
    std::atomic<long> draws{0};
    const RenderResult uniform = render_paths(UniformTracer{tracer, draws}, camera, settings);
    const RenderResult bsdf = render_paths(tracer, camera, settings);
    // Each vertex on the sphere drew once, and its ray escaped: one indirect ray per draw.
    CHECK(draws > 0);
    CHECK(draws == long(uniform.rays[RayKind::kIndirect]));
    CHECK(uniform.image.pixels() != bsdf.image.pixels());  // the vertex's own sampling, not the BSDF's
    // The same mean: MIS weighed the environment's samples against the density the vertex drew with.
    double sum = 0, pixels = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            if (wholly_on_unit_sphere(camera, x, y)) {
                sum += double(uniform.image.at(x, y).g);
                ++pixels;
            }
    REQUIRE(pixels > 200);
    CHECK(sum / pixels == Approx(0.5).epsilon(0.01));
}

TEST_CASE("Every strategy converges to the same image on the chapter's scene",
          "[render][statistical][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch04.uniform_hemisphere][ex:ch04.uniform_hemisphere_pdf][ex:ch05.termination]"
          "[ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    const Scene scene = load_scene(scene_path("ch06_default.json"));
    // The image cut into 2×2 blocks; each block's mean over kRuns independent renders, with its standard
    // error.
    constexpr int kSize = 16, kSpp = 16, kRuns = 8;
    auto blocks_of = [&](SamplingStrategy s) {
        return test::block_means(kSize, kRuns, [&](std::uint64_t seed) {
            const RenderResult result = render_scene(scene, s, kSize, kSpp, seed, 2);
            REQUIRE(result.image.all_finite());
            return result.image;
        });
    };
    const test::BlockMeans reference = blocks_of(SamplingStrategy::kMis);
    for (SamplingStrategy s : {SamplingStrategy::kUniform, SamplingStrategy::kCosine, SamplingStrategy::kBrdf,
                               SamplingStrategy::kLight}) {
        const test::BlockMeans other = blocks_of(s);
        for (int b = 0; b < 4; ++b) {
            const double sigma =
                std::sqrt(reference.error[b] * reference.error[b] + other.error[b] * other.error[b]);
            INFO(to_string(s) << " block " << b << ": " << other.mean[b] << " +- " << other.error[b]
                              << ", mis " << reference.mean[b] << " +- " << reference.error[b]);
            CHECK(std::abs(other.mean[b] - reference.mean[b]) <= 4.5 * sigma);
            CHECK(other.error[b] > 0);
        }
    }
}

TEST_CASE("MIS has far less error than uniform or cosine sampling for the same samples",
          "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch04.uniform_hemisphere][ex:ch04.uniform_hemisphere_pdf][ex:ch05.termination]"
          "[ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    const Scene scene = load_scene(scene_path("ch06_default.json"));
    const RenderResult reference = render_scene(scene, SamplingStrategy::kMis, 24, 256, 99, 2);
    // The relative MSE of error_metrics.hpp: the lamp's own edge, seen directly, does not swamp the rest.
    auto error = [&](SamplingStrategy s) {
        return compare(render_scene(scene, s, 24, 8, 3, 2).image, reference.image).relative_mse;
    };
    const double uniform = error(SamplingStrategy::kUniform), cosine = error(SamplingStrategy::kCosine),
                 mis = error(SamplingStrategy::kMis);
    INFO("relative MSE at 8 spp: uniform " << uniform << ", cosine " << cosine << ", mis " << mis);
    // Without light sampling a pixel's light comes from the rare paths that hit the small lamp: a few huge
    // samples. With it, every vertex sees the lamp.
    CHECK(mis < cosine / 10);
    CHECK(mis < uniform / 10);
}

TEST_CASE(
    "Ray counts: shadow rays only with light sampling, none without lights, the same image on 1 and 2 "
    "threads",
    "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
    "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
    "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
    "[ex:ch04.uniform_hemisphere][ex:ch04.uniform_hemisphere_pdf][ex:ch05.termination]"
    "[ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    const Scene scene = load_scene(scene_path("ch06_default.json"));
    const RenderResult one = render_scene(scene, SamplingStrategy::kMis, 24, 4, 5, 1);
    const RenderResult two = render_scene(scene, SamplingStrategy::kMis, 24, 4, 5, 2);
    CHECK(one.image.pixels() == two.image.pixels());
    CHECK(one.image.all_finite());
    CHECK(one.image.mean() > 0.05);
    CHECK(one.image.mean() < 0.5);
    CHECK(one.rays[RayKind::kCamera] == 24u * 24u * 4u);
    CHECK(one.rays[RayKind::kShadow] > 0);
    CHECK(one.rays[RayKind::kIndirect] > 0);
    CHECK(one.rays[RayKind::kRefraction] == 0);
    for (SamplingStrategy s :
         {SamplingStrategy::kUniform, SamplingStrategy::kCosine, SamplingStrategy::kBrdf}) {
        CHECK(render_scene(scene, s, 8, 2, 5).rays[RayKind::kShadow] == 0);
    }
    Scene dark = scene;
    for (Material& m : dark.materials) m.emission = Color(0);
    const RenderResult black = render_scene(dark, SamplingStrategy::kMis, 8, 2, 5);
    CHECK(black.rays[RayKind::kShadow] == 0);
    CHECK(black.image.mean() == 0);
}

TEST_CASE(
    "Inside a closed box of emitters, emission 0.5 and albedo 0.5, every strategy sees Le / (1 - rho) = 1",
    "[render][statistical][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
    "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
    "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    // Every point sees only walls of the same radiance L = Le + ρ L: L = 1 at every bounce, so a path whose
    // later vertices are weighed wrongly (its throughput left out of next-event estimation, a light counted
    // by both strategies) is off by a multiple of the light of those bounces.
    const Scene scene = test::closed_box_scene();
    for (SamplingStrategy s : {SamplingStrategy::kBrdf, SamplingStrategy::kLight, SamplingStrategy::kMis}) {
        const RenderResult r = render_scene(scene, s, 8, 64, 5, 2);
        INFO("strategy " << int(s));
        REQUIRE(r.image.all_finite());
        CHECK(r.image.mean() == Approx(1).epsilon(0.03));
    }
}

TEST_CASE("An emissive plane, which no light sample can reach, is seen by every strategy",
          "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch05.termination]"
          "[ex:ch06.path_tracer]") {
    // A diffuse sphere under an emissive plane (radiance 1, facing down): light, mis and cosine agree.
    Scene scene = furnace_scene(0.5f);
    scene.environment.reset();
    Material lamp;
    lamp.name = "sky";
    lamp.albedo = Color(0);
    lamp.emission = Color(1);
    scene.materials.push_back(lamp);
    scene.shapes.push_back(Shape{PlaneShape{{0, 3, 0}, {0, -1, 0}}, 1, "shapes[1]"});
    scene.camera = CameraDesc{{0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 30};
    REQUIRE(collect_lights(scene).unsampled.size() == 1);
    const double cosine = render_scene(scene, SamplingStrategy::kCosine, 16, 64, 1).image.mean();
    for (SamplingStrategy s : {SamplingStrategy::kLight, SamplingStrategy::kMis}) {
        const RenderResult r = render_scene(scene, s, 16, 64, 1);
        INFO(to_string(s) << ": " << r.image.mean() << ", cosine " << cosine);
        CHECK(r.image.mean() == Approx(cosine).epsilon(0.03));
        CHECK(r.image.mean() > 0.1);
    }
}

// A diffuse sphere under a 4 x 4 lamp at y = 3 (radiance 1: a quad, or its two triangles), its front down
// toward the sphere or up away from it, one-sided or two-sided; the mean of chapter 06's image by `strategy`.
double under_lamp(bool triangles, bool front_down, bool two_sided, SamplingStrategy strategy) {
    Scene scene = furnace_scene(0.5f);
    scene.environment.reset();
    Material lamp;
    lamp.name = "lamp";
    lamp.albedo = Color(0);
    lamp.emission = Color(1);
    lamp.two_sided = two_sided;
    scene.materials.push_back(lamp);
    const Vec3 o(-2, 3, -2), x(4, 0, 0), z(0, 0, 4);  // x × z points down
    const Vec3 u = front_down ? x : z, v = front_down ? z : x;
    if (triangles) {
        scene.shapes.push_back(Shape{TriangleShape{{o, o + u, o + u + v}}, 1, "shapes[1]"});
        scene.shapes.push_back(Shape{TriangleShape{{o, o + u + v, o + v}}, 1, "shapes[2]"});
    } else {
        scene.shapes.push_back(Shape{QuadShape{o, u, v}, 1, "shapes[1]"});
    }
    scene.camera = CameraDesc{{0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 30};  // the lamp is out of view
    return render_scene(scene, strategy, 16, 64, 1).image.mean();
}

TEST_CASE(
    "A two-sided lamp (a quad, two triangles) lights both half-spaces equally, by light and by BSDF "
    "sampling, a one-sided one only its front",
    "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.triangle_watertight]"
    "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
    "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light][ex:ch04.uniform_triangle]"
    "[ex:ch04.uniform_hemisphere][ex:ch04.uniform_hemisphere_pdf][ex:ch05.termination]"
    "[ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    const double facing = under_lamp(false, true, false, SamplingStrategy::kMis);
    REQUIRE(facing > 0.01);
    for (bool triangles : {false, true}) {
        for (SamplingStrategy s :
             {SamplingStrategy::kCosine, SamplingStrategy::kLight, SamplingStrategy::kMis}) {
            INFO(to_string(s) << (triangles ? ", triangles" : ", a quad")
                              << "; the one-sided quad facing the sphere: " << facing);
            CHECK(under_lamp(triangles, true, true, s) == Approx(facing).epsilon(0.03));
            CHECK(under_lamp(triangles, false, true, s) == Approx(facing).epsilon(0.03));
            CHECK(under_lamp(triangles, false, false, s) == 0);
        }
    }
}

TEST_CASE("Sampling strategies are named on the command line", "[strategy]") {
    for (SamplingStrategy s : kAllStrategies) CHECK(from_string<SamplingStrategy>(to_string(s)) == s);
    CHECK_THROWS_AS(from_string<SamplingStrategy>("importance"), InputError);
}

TEST_CASE("Roulette judges beta with the samples' radiance scale divided out: a path through glass is not "
          "made rarer and brighter, and either way the estimate stays unbiased",
          "[roulette][ex:ch05.termination]") {
    // Roulette reads no scene: an empty one, under chapter 06's default rule (from kPathRouletteStart).
    const RenderScene prepared(Scene{}, EffectSet::all());
    const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, PathOptions{});
    // A path of throughput 0.9 enters glass of η = 1.5: refraction scales its radiance by 1/η², so β is 0.4
    // inside, and the η-scale the loop carries is η² = 2.25 (it leaves with β × η² again).
    const Real eta2 = Real(2.25), inside = Real(0.9) / eta2;
    // Judged as it will leave, it goes on with q = 0.9, at β / q; judged on β itself (the naive rule) with
    // q = 0.4, and its survivors leave 1 / 0.4 times brighter than they came in.
    int robust_survived = 0, naive_survived = 0;
    double robust_sum = 0, naive_sum = 0;
    Real robust_leaving = 0, naive_leaving = 0;  // the brightest survivor's β × η² once out of the glass
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        Pcg32 a = Pcg32::for_sample(0, std::uint64_t(i), 7), b = a;
        Color beta_robust(inside), beta_naive(inside);
        if (tracer.roulette(kPathRouletteStart, beta_robust, eta2, a)) {
            ++robust_survived;
            robust_sum += double(beta_robust.g);
            robust_leaving = std::max(robust_leaving, beta_robust.g * eta2);
        }
        if (tracer.roulette(kPathRouletteStart, beta_naive, 1, b)) {
            ++naive_survived;
            naive_sum += double(beta_naive.g);
            naive_leaving = std::max(naive_leaving, beta_naive.g * eta2);
        }
    }
    // A survivor leaves the glass with β η² = 0.9 / q: 1 judged as it will leave, 2.25 judged on β inside.
    CHECK(robust_leaving == Approx(1.0));
    CHECK(naive_leaving == Approx(2.25));
    // Survival: 0.9 judged as it will leave, 0.4 judged on β inside; both unbiased: E[β'] = β.
    CHECK(double(robust_survived) / n == Approx(0.9).margin(5 * std::sqrt(0.9 * 0.1 / n)));
    CHECK(double(naive_survived) / n == Approx(0.4).margin(5 * std::sqrt(0.4 * 0.6 / n)));
    CHECK(robust_sum / n == Approx(double(inside)).margin(5 * double(inside) * std::sqrt((1 / 0.9 - 1) / n)));
    CHECK(naive_sum / n == Approx(double(inside)).margin(5 * double(inside) * std::sqrt((1 / 0.4 - 1) / n)));
}

// ---------------------------------------------------------------------------------------------------------
// The environment image: its 2-D distribution, the lat-long Jacobian, and the path tracer under it

namespace {

// A small map with a bright "sun" pixel, a dim sky above the horizon, a darker ground and black columns:
// every kind of cell the distribution meets (0, tiny, huge). With `lit_poles`, bright cells in the rows at
// the poles, where p(ω) grows as 1 / sin θ: integrable, but no numerical integration of the chi-square
// harness's expected counts converges there, so the chi-square test takes the rows at the poles black.
std::shared_ptr<Image> test_sky(bool lit_poles, int width = 16, int height = 8) {
    auto image = std::make_shared<Image>(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const Real sky = y < height / 2 ? Real(0.5 + 0.1 * x / width) : Real(0.1);
            image->at(x, y) = x % 7 == 3 ? Color(0) : Color(sky, sky, Real(1.2) * sky);
        }
    }
    image->at(width / 3, height / 4) = Color(200, 180, 150);  // the sun
    for (int x = 0; x < width; ++x) {
        image->at(x, 0) = lit_poles && x == 1 ? Color(5) : Color(0);                  // the top pole's row
        image->at(x, height - 1) = lit_poles && x == width - 2 ? Color(3) : Color(0);  // the bottom one's
    }
    return image;
}

EnvironmentLight image_light(std::shared_ptr<const Image> image, Real rotate_y = 0, Real scale = 1) {
    EnvironmentLight light;
    light.image = std::move(image);
    light.scale = scale;
    light.rotate_y = rotate_y;
    return light;
}

}  // namespace

TEST_CASE("Distribution1D: a sample's pdf is its cell's weight over the mean, cells of weight 0 never drawn",
          "[environment]") {
    const Distribution1D d({1, 0, 3, 0});
    CHECK(d.integral() == Approx(1.0));
    CHECK(d.pdf(0) == Approx(1.0));
    CHECK(d.pdf(1) == 0);
    CHECK(d.pdf(2) == Approx(3.0));
    Pcg32 rng(7, 1);
    int in_cell[4] = {0, 0, 0, 0};
    for (int i = 0; i < 40000; ++i) {
        const Distribution1D::Sample s = d.sample(rng.next_real());
        REQUIRE(s.x >= 0);
        REQUIRE(s.x < 1);
        REQUIRE(s.cell == std::min(3, int(s.x * 4)));
        ++in_cell[s.cell];
    }
    CHECK(in_cell[1] == 0);
    CHECK(in_cell[3] == 0);
    CHECK(in_cell[2] == Approx(30000).margin(400));  // 3/4 of the samples, σ ≈ 87
    // The ends of [0, 1): the first and last cells of weight > 0, x inside [0, 1).
    CHECK(d.sample(0).cell == 0);
    CHECK(d.sample(kOneMinusEpsilon).cell == 2);
    CHECK(d.sample(kOneMinusEpsilon).x < Real(0.75));
    // All weights 0: uniform, not 0/0.
    const Distribution1D zero({0, 0});
    CHECK(zero.pdf(1) == 1);
    CHECK(std::isfinite(zero.sample(Real(0.7)).x));
}

TEST_CASE("Distribution2D: p(u, v) = w / mean w, and the marginal times the conditional draws it",
          "[environment]") {
    const std::vector<double> w{1, 2, 0, 0, 0, 0, 3, 6};  // 4 × 2; row 1's cells 0 and 1 are 0
    const Distribution2D d(w, 4, 2);
    CHECK(d.integral() == Approx(12.0 / 8));
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 4; ++i) CHECK(d.pdf(i, j) == Approx(w[std::size_t(j * 4 + i)] / 1.5));
    Pcg32 rng(9, 1);
    std::vector<int> count(8, 0);
    constexpr int kN = 120000;
    for (int n = 0; n < kN; ++n) {
        const Distribution2D::Sample s = d.sample(rng.next_vec2());
        REQUIRE(s.pdf == Approx(d.pdf(s.i, s.j)));
        REQUIRE(s.i == std::min(3, int(s.uv.x * 4)));
        REQUIRE(s.j == std::min(1, int(s.uv.y * 2)));
        ++count[std::size_t(s.j * 4 + s.i)];
    }
    for (std::size_t c = 0; c < 8; ++c) CHECK(count[c] == Approx(kN * w[c] / 12).margin(5 * std::sqrt(kN / 4.0)));
}

TEST_CASE("The lat-long map: direction(uv) and point(w) are inverse, and sin θ is the Jacobian's", "[environment]") {
    const LatLongMap map = LatLongMap::turned_by_degrees(30);
    Pcg32 rng(3, 1);
    for (int n = 0; n < 1000; ++n) {
        const Vec2 uv = rng.next_vec2();
        const Vec3 w = map.direction(uv);
        REQUIRE(glm::length(w) == Approx(1).epsilon(1e-5));
        const LatLongMap::Point p = map.point(w);
        // u wraps at 1; compare on the circle.
        const Real du = std::abs(p.uv.x - uv.x);
        CHECK(std::min(du, 1 - du) < 1e-4f);
        CHECK(p.uv.y == Approx(uv.y).margin(1e-4));
        CHECK(p.sin_theta == Approx(std::sin(kPi * uv.y)).margin(1e-5));
    }
}

TEST_CASE("The environment image's sampler fits its pdf (chi-square), which integrates to 1 over the sphere",
          "[environment][statistical]") {
    for (Real rotate : {0.0f, 75.0f}) {
        const Environment environment(image_light(test_sky(false), rotate));
        REQUIRE_FALSE(environment.black());
        const Vec3 n(0, 0, 1);  // any normal: the image's density is the same everywhere
        const ChiSquare r = test_directions(
            [&](Vec2 u) {
                const EnvironmentSample s = environment.sample(n, u);
                // The sample's pdf is the pdf evaluated for its direction.
                if (s.pdf > 0) REQUIRE(s.pdf == Approx(environment.pdf(n, s.wi)).epsilon(1e-3));
                return Drawn{s.wi, double(s.pdf), !(s.pdf > 0)};
            },
            [&](const Vec3& w) { return double(environment.pdf(n, w)); }, 700 + std::uint64_t(rotate));
        INFO("rotate_y " << rotate);
        require_fit(r, kAlphaPerTest);
        CHECK(r.expected_total / r.samples == Approx(1).epsilon(2e-3));
        CHECK(r.lost == 0);
    }
}

TEST_CASE("No NaN or infinity at the poles: sin θ from the direction, not from acos(y)", "[environment][stability]") {
    const Environment environment(image_light(test_sky(true)));
    const Vec3 n(0, 1, 0);
    // The naive way: θ = acos(y) in float. A direction 1e-4 from the pole has y = 1 − 5e-9, which float rounds
    // to 1: θ = 0, sin θ = 0, and p(u, v) / (2π² sin θ) is infinite although the direction is not the pole.
    const Vec3 near_pole = glm::normalize(Vec3(0.866e-4f, 1, 0.5e-4f));  // φ = 30°: the lit pixel (1, 0)
    const float naive_sin = std::sin(std::acos(near_pole.y));
    CHECK(naive_sin == 0.0f);
    CHECK(std::isinf(1.0f / naive_sin));
    // The robust way: sin θ = √(x² + z²).
    const Real robust = environment.pdf(n, near_pole);
    CHECK(std::isfinite(robust));
    CHECK(robust > 0);
    // The poles themselves: no density (a point of measure 0), never NaN.
    CHECK(environment.pdf(n, Vec3(0, 1, 0)) == 0);
    CHECK(environment.pdf(n, Vec3(0, -1, 0)) == 0);
    CHECK(is_finite(environment.radiance(Vec3(0, 1, 0))));
    // Samples at the ends of [0, 1)²: a finite direction, a finite pdf (0 skips it), finite radiance.
    for (Real a : {Real(0), Real(1e-7), kOneMinusEpsilon})
        for (Real b : {Real(0), Real(1e-7), kOneMinusEpsilon}) {
            const EnvironmentSample s = environment.sample(n, Vec2(a, b));
            INFO("u = " << a << ", " << b);
            CHECK(is_finite(s.wi));
            CHECK(std::isfinite(s.pdf));
            CHECK(s.pdf >= 0);
            CHECK(is_finite(s.radiance));
            if (s.pdf > 0) CHECK(std::isfinite(luminance(s.radiance) / s.pdf));
        }
}

TEST_CASE("rotate_y turns the map about +y", "[environment]") {
    auto image = std::make_shared<Image>(8, 4);
    image->at(0, 1) = Color(1);  // one lit pixel: u in [0, 1/8), just above the horizon, toward +x
    const Environment still(image_light(image, 0)), turned(image_light(image, 90));
    const Vec3 plus_x = glm::normalize(Vec3(1, 0.4f, 0.2f));
    CHECK(still.radiance(plus_x) == Color(1));
    CHECK(turned.radiance(plus_x) == Color(0));
    // R_y(90°) takes +x to −z, as a shape's rotate_y does.
    const Vec3 minus_z = glm::normalize(Vec3(0.2f, 0.4f, -1));
    CHECK(turned.radiance(minus_z) == Color(1));
    CHECK(turned.pdf(Vec3(0), minus_z) == Approx(still.pdf(Vec3(0), plus_x)).epsilon(1e-3));
    // Every sample of the turned map is the still map's turned.
    Pcg32 rng(5, 1);
    for (int n = 0; n < 100; ++n) {
        const Vec2 u = rng.next_vec2();
        const Vec3 a = still.sample(Vec3(0), u).wi, b = turned.sample(Vec3(0), u).wi;
        CHECK(b.x == Approx(a.z).margin(1e-5));
        CHECK(b.z == Approx(-a.x).margin(1e-5));
        CHECK(b.y == a.y);
    }
}

TEST_CASE(
    "Furnace: a constant image equal to the uniform sky gives the same image within noise (its samples differ)",
    "[render][environment][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable]"
    "[ex:ch03.robust_offset][ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch05.termination]"
    "[ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    constexpr Real kAlbedo = 0.5f;
    constexpr int kSize = 24, kSpp = 16;
    Scene constant = furnace_scene(kAlbedo);
    Scene mapped = constant;
    auto ones = std::make_shared<Image>(32, 16);
    for (Color& c : ones->pixels()) c = Color(1);
    mapped.environment = image_light(ones);
    const RenderResult a = render_scene(constant, SamplingStrategy::kMis, kSize, kSpp, 4);
    const RenderResult b = render_scene(mapped, SamplingStrategy::kMis, kSize, kSpp, 4);
    REQUIRE(b.image.all_finite());
    // The background is the map itself, exactly. The map's directions fall below the surface half the time
    // (no shadow ray then); the constant sky's never do.
    CHECK(b.image.at(0, 0) == Color(1));
    CHECK(b.rays[RayKind::kShadow] > 0);
    CHECK(b.rays[RayKind::kShadow] < a.rays[RayKind::kShadow]);
    const PinholeCamera camera = make_pinhole_camera(constant.camera, kSize, kSize);
    // On the sphere: ρ · 1. The constant sky is drawn cosine-weighted (MIS against the cosine BSDF: zero
    // variance); the map is drawn by sin θ, uniform over the sphere, so its estimate is noisy but unbiased.
    double sum = 0, sum2 = 0, n = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (!wholly_on_unit_sphere(camera, x, y)) continue;
            CHECK(a.image.at(x, y).g == Approx(kAlbedo).epsilon(1e-5));
            const double v = b.image.at(x, y).g;
            sum += v, sum2 += v * v, ++n;
        }
    REQUIRE(n > 100);
    const double mean = sum / n, standard_error = std::sqrt((sum2 / n - mean * mean) / (n - 1));
    INFO("constant map on the sphere: " << mean << " +- " << standard_error);
    CHECK(standard_error > 0);
    CHECK(std::abs(mean - kAlbedo) <= 4 * standard_error);
}

TEST_CASE("An environment image: every strategy converges to the same image, MIS with the least error",
          "[render][environment][statistical][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.uniform_hemisphere]"
          "[ex:ch04.uniform_hemisphere_pdf][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    Scene scene = furnace_scene(0.7f);
    scene.environment = image_light(test_sky(true), 40);
    constexpr int kSize = 12, kRuns = 6;
    auto mean_of = [&](SamplingStrategy s, int spp, double& error) {
        double sum = 0, sum2 = 0;
        for (int r = 0; r < kRuns; ++r) {
            const RenderResult result = render_scene(scene, s, kSize, spp, 60 + std::uint64_t(r));
            REQUIRE(result.image.all_finite());
            const double m = result.image.mean();
            sum += m, sum2 += m * m;
        }
        const double mean = sum / kRuns;
        error = std::sqrt(std::max(0.0, sum2 / kRuns - mean * mean) / (kRuns - 1));
        return mean;
    };
    double mis_error = 0, light_error = 0, cosine_error = 0;
    const double mis = mean_of(SamplingStrategy::kMis, 16, mis_error);
    const double light = mean_of(SamplingStrategy::kLight, 16, light_error);
    const double cosine = mean_of(SamplingStrategy::kCosine, 64, cosine_error);
    INFO("mis " << mis << " +- " << mis_error << ", light " << light << " +- " << light_error << ", cosine "
                << cosine << " +- " << cosine_error);
    CHECK(std::abs(light - mis) <= 4.5 * std::hypot(light_error, mis_error));
    CHECK(std::abs(cosine - mis) <= 4.5 * std::hypot(cosine_error, mis_error));
    CHECK(mis_error < cosine_error);
}
