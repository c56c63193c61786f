// Chapter 05: recursive global illumination. The termination rules (which stop where, and roulette's
// unbiasedness), the furnace's closed forms against the recursive trace for several albedos and depths,
// emission counted exactly once, mirror reflection (direction and energy), two mirrors facing each other,
// grazing rays, ray counts by effect, and the default scene end to end.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "05_recursive_gi/furnace.hpp"
#include "05_recursive_gi/gi_render.hpp"
#include "05_recursive_gi/recursive_tracer.hpp"
#include "05_recursive_gi/scatter.hpp"
#include "05_recursive_gi/termination.hpp"
#include "05_recursive_gi/termination_flags.hpp"
#include "random_unit.hpp"
#include "rt/io/effects.hpp"
#include "rt/core/errors.hpp"
#include "rt/core/random.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"

using namespace rt;

namespace {

// A Monte Carlo estimate: the mean of n samples and its standard error.
struct Estimate {
    double mean = 0;
    double error = 0;  // standard error of the mean, from the samples' spread
};

Estimate estimate(int n, const std::function<double()>& sample) {
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        const double x = sample();
        sum += x;
        sum2 += x * x;
    }
    const double mean = sum / n;
    const double variance = std::max(0.0, (sum2 / n - mean * mean) * n / (n - 1));
    return {mean, std::sqrt(variance / n)};
}

TerminationSettings rule(Termination t, int max_depth, Real min_throughput = Real(0.01), int start = 3) {
    return TerminationSettings{t, max_depth, min_throughput, start};
}

// Everything a trace needs, kept alive together (the tracer holds references to the rest).
struct Setup {
    Scene scene;
    std::unique_ptr<World> world;
    std::unique_ptr<MaterialTable> materials;
    std::unique_ptr<DirectLighting> shading;
    std::unique_ptr<RecursiveTracer> tracer;

    // The effects simulated are direct.simulated when given, else what a run of chapter 05 simulates for
    // the scene (simulated_effects: needed ∩ supported), as for a user's scene file.
    Setup(Scene s, TerminationSettings termination, std::optional<DirectOptions> given = std::nullopt)
        : scene(std::move(s)) {
        DirectOptions direct = given.value_or(DirectOptions{});
        if (!given) direct.simulated = simulated_effects(scene, kRecursiveChapterEffects);
        world = std::make_unique<World>(scene);
        materials = std::make_unique<MaterialTable>(scene, direct.simulated);
        shading = std::make_unique<DirectLighting>(*world, *materials, collect_lights(scene), direct);
        tracer = std::make_unique<RecursiveTracer>(*shading, GiOptions{termination});
    }
};

DirectOptions simulating(const EffectSet& effects) {
    DirectOptions options;
    options.simulated = effects;
    return options;
}

Material diffuse(Color albedo, Color emission = Color(0)) {
    Material m;
    m.type = "diffuse";
    m.albedo = albedo;
    m.emission = emission;
    return m;
}

Material mirror(Color reflectance) {
    Material m;
    m.type = "mirror";
    m.reflectance = reflectance;
    return m;
}

Shape quad(Vec3 origin, Vec3 u, Vec3 v, int material) {
    return Shape{QuadShape{origin, u, v}, material, "test"};
}

// The green channel of the radiance along rays from the camera in uniformly random directions.
Estimate furnace_estimate(const Setup& setup, int n, std::uint64_t seed, RayCounts* counts = nullptr) {
    Pcg32 directions(seed, 1);
    RayCounts rays;
    std::uint64_t path = 0;
    const Estimate e = estimate(n, [&] {
        const Ray ray{setup.scene.camera.from, random_unit(directions)};
        Pcg32 rng = Pcg32::for_sample(0, path++, seed);  // one stream per path, as in a render
        return double(setup.tracer->radiance(ray, rng, rays).g);
    });
    if (counts) *counts = rays;
    return e;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Termination

TEST_CASE("Termination rules are named depth, throughput and roulette, and other names are refused",
          "[termination]") {
    CHECK(from_string<Termination>("depth") == Termination::kMaxDepth);
    CHECK(from_string<Termination>("throughput") == Termination::kMinThroughput);
    CHECK(from_string<Termination>("roulette") == Termination::kRussianRoulette);
    for (Termination t :
         {Termination::kMaxDepth, Termination::kMinThroughput, Termination::kRussianRoulette}) {
        CHECK(from_string<Termination>(to_string(t)) == t);
    }
    CHECK_THROWS_AS(from_string<Termination>("Depth"), InputError);
    CHECK_THROWS_WITH(from_string<Termination>("rr"),
                      Catch::Contains("--termination") && Catch::Contains("rr"));
    const TerminationSettings defaults;
    CHECK(defaults.rule == Termination::kRussianRoulette);
    CHECK(defaults.max_depth == 8);
    CHECK(defaults.roulette_start_depth == 3);
}

TEST_CASE("The depth rule bounces exactly max_depth times and leaves the throughput alone",
          "[termination][ex:ch05.termination]") {
    for (int n : {0, 1, 4, 16}) {
        const TerminationSettings s = rule(Termination::kMaxDepth, n);
        for (int depth = 0; depth < n + 3; ++depth) {
            Color beta(0.001f, 0.2f, 0.5f);
            INFO("max depth " << n << ", depth " << depth);
            CHECK(continue_path(s, depth, beta, 0.999f) == (depth < n));
            CHECK(beta == Color(0.001f, 0.2f, 0.5f));
        }
    }
}

TEST_CASE("The throughput rule stops below its threshold, and at the cap",
          "[termination][ex:ch05.termination]") {
    const TerminationSettings s = rule(Termination::kMinThroughput, 10, Real(0.1));
    Color beta(0.05f, 0.11f, 0.0f);  // max component 0.11: bright enough
    CHECK(continue_path(s, 5, beta, 0.5f));
    CHECK(beta == Color(0.05f, 0.11f, 0.0f));
    beta = Color(0.09f);
    CHECK_FALSE(continue_path(s, 5, beta, 0.0f));
    beta = Color(1);
    CHECK_FALSE(continue_path(s, 10, beta, 0.0f));  // the hard cap
}

TEST_CASE("Russian roulette stays unbiased and weights a survivor's largest channel up to 1",
          "[termination][statistical][ex:ch05.termination]") {
    const TerminationSettings s = rule(Termination::kRussianRoulette, 64, Real(0.01), 3);
    for (const Color& beta : {Color(0.3f, 0.12f, 0.06f), Color(0.02f, 0.9f, 0.5f), Color(0.3f, 1.7f, 0.2f)}) {
        const Real q = survival_probability(s, 5, beta);
        INFO("throughput (" << beta.r << ", " << beta.g << ", " << beta.b << "): q = " << q);
        {
            INFO("q is not a probability: it must lie in [0, 1]");
            CHECK((q >= 0 && q <= 1));
        }
        Color survivor = beta;
        if (continue_path(s, 5, survivor, 0.0f)) {
            INFO("a survivor's largest channel must be weighted up to 1 (or left alone when it is 1 or more)");
            CHECK(std::max({survivor.r, survivor.g, survivor.b}) ==
                  Approx(std::max(Real(1), std::max({beta.r, beta.g, beta.b}))));
        }
    }
    // Before the start depth, and for q >= 1, it never kills and never rescales.
    for (int depth = 0; depth < 3; ++depth) {
        Color beta(0.01f);
        CHECK(continue_path(s, depth, beta, kOneMinusEpsilon));
        CHECK(beta == Color(0.01f));
    }
    Color bright(0.3f, 1.7f, 0.2f);
    CHECK(continue_path(s, 20, bright, kOneMinusEpsilon));
    CHECK(bright == Color(0.3f, 1.7f, 0.2f));
    // E[β'] = β (β' = β / q on survival, 0 otherwise), and the survival rate is q = 0.3.
    const Color beta0(0.3f, 0.12f, 0.06f);
    Pcg32 rng(500, 0);
    int survived = 0;
    constexpr int kTrials = 200000;
    const Estimate mean = estimate(kTrials, [&] {
        Color beta = beta0;
        if (!continue_path(s, 5, beta, rng.next_real())) return 0.0;
        ++survived;
        CHECK(beta.r == Approx(1.0));
        return double(beta.g);
    });
    {
        INFO("E[beta'] = " << mean.mean << ", not beta = 0.12: the survivors' weight does not make up for the "
                                           "stopped paths (biased)");
        CHECK(std::abs(mean.mean - 0.12) <= 4 * mean.error);
    }
    const double rate = double(survived) / kTrials;
    CHECK(std::abs(rate - 0.3) <= 4 * std::sqrt(0.3 * 0.7 / kTrials));
    // The cap ends it whatever the throughput; a black or NaN throughput ends it at once.
    Color one(1);
    CHECK_FALSE(continue_path(s, 64, one, 0.0f));
    Color black(0);
    CHECK_FALSE(continue_path(rule(Termination::kMaxDepth, 8), 0, black, 0.0f));
    Color nan(std::nanf(""), 1, 1);
    CHECK_FALSE(continue_path(s, 0, nan, 0.0f));
}

// ---------------------------------------------------------------------------------------------------------
// The furnace

TEST_CASE("The furnace's closed forms: L_N = Le (1 - rho^(N+1)) / (1 - rho) tends to Le / (1 - rho)",
          "[furnace]") {
    const Furnace f{Color(0.5f), Color(2)};
    CHECK(furnace_radiance(f).y == Approx(4));
    CHECK(furnace_radiance_truncated(f, 0).y == Approx(2));
    CHECK(furnace_radiance_truncated(f, 1).y == Approx(3));
    CHECK(furnace_radiance_truncated(f, 2).y == Approx(3.5));
    CHECK(furnace_radiance_truncated(f, 60).y == Approx(4).epsilon(1e-12));
    const Furnace coloured{Color(0, 0.25f, 0.75f), Color(1)};
    CHECK(furnace_radiance(coloured).x == Approx(1));
    CHECK(furnace_radiance(coloured).z == Approx(4));
}

TEST_CASE("The furnace scene is recognised, and the default scene is not", "[furnace][ex:ch02.quad_packet]") {
    const Scene furnace_file = load_scene(scene_path("ch05_furnace.json"));
    const World world(furnace_file);
    const auto found = find_furnace(furnace_file, world);
    REQUIRE(found);
    CHECK(found->albedo == Color(0.8f));
    CHECK(found->emission == Color(1));
    const Scene made = make_furnace_scene({Color(0.3f), Color(1)}, {0.5f, 0.2f, -0.7f});
    CHECK(find_furnace(made, World(made)));
    const Scene cornell = load_scene(scene_path("ch05_default.json"));
    CHECK_FALSE(find_furnace(cornell, World(cornell)));
    // A box with one wall missing is not closed.
    Scene open = made;
    open.shapes.pop_back();
    CHECK_FALSE(find_furnace(open, World(open)));
}

// Light sampling in a box has a heavy tail: a wall point near an edge samples the neighbouring wall at a
// distance d → 0, where f Le cos θ cos θ_l A / d² is unbounded, and its variance is infinite (the lesson
// shows it). Error bars need a finite variance, so the recursion's closed forms are checked with the walls'
// light found by indirect rays alone (effect "direct" off), where a path adds Le β_k at its k-th vertex with
// β_k <= (2ρ)^k up to the cap: bounded; light sampling is checked where its samples are bounded (below).
DirectOptions indirect_rays_alone() {
    return simulating(EffectSet::all().without({Effect::kDirect}));
}

TEST_CASE("Cut after N bounces, the furnace gives Le (1 - rho^(N+1)) / (1 - rho) within its error bars",
          "[furnace][statistical][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch04.lambert]"
          "[ex:ch04.uniform_hemisphere][ex:ch05.termination][ex:ch05.trace][ex:ch05.uniform_scatter]") {
    std::uint64_t seed = 600;
    for (Real rho : {0.2f, 0.5f, 0.8f}) {
        const Furnace furnace{Color(rho), Color(1.5f)};
        for (int n : {0, 1, 2, 3, 6, 12}) {
            INFO("rho " << rho << ", N = " << n);
            const Setup setup(make_furnace_scene(furnace, {0.3f, -0.2f, 0.1f}),
                              rule(Termination::kMaxDepth, n), indirect_rays_alone());
            RayCounts rays;
            const Estimate e = furnace_estimate(setup, 4000, ++seed, &rays);
            const double expected = furnace_radiance_truncated(furnace, n).y;
            CHECK(rays[RayKind::kIndirect] == std::uint64_t(4000 * n));  // a closed box: every path goes on
            if (n == 0) {
                CHECK(e.mean == Approx(1.5));  // emission only: no noise at all
                CHECK(e.error == 0);
            } else {
                CHECK(e.error > 0);
                CHECK(std::abs(e.mean - expected) <= 4 * e.error);
            }
            // The bias of the cut is real: at N = 2 and rho = 0.8 it is 3.9 Le, far outside the error bars.
            if (n == 2 && rho == 0.8f) CHECK(furnace_radiance(furnace).y - e.mean > 20 * e.error);
        }
    }
}

TEST_CASE("Russian roulette is unbiased in the furnace, the throughput rule is biased low",
          "[furnace][statistical][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch04.lambert]"
          "[ex:ch04.uniform_hemisphere][ex:ch05.termination][ex:ch05.trace][ex:ch05.uniform_scatter]") {
    std::uint64_t seed = 700;
    for (Real rho : {0.3f, 0.6f, 0.8f}) {
        INFO("rho " << rho);
        const Furnace furnace{Color(rho), Color(1)};
        const Scene scene = make_furnace_scene(furnace, {-0.4f, 0.1f, 0.2f});
        const Setup roulette(scene, rule(Termination::kRussianRoulette, kSafetyDepthCap),
                             indirect_rays_alone());
        const Estimate e = furnace_estimate(roulette, 6000, ++seed);
        CHECK(std::abs(e.mean - furnace_radiance(furnace).y) <= 4 * e.error);
    }
    // min throughput 0.5 with ρ = 0.8: uniform directions have weight 2 ρ cos θ, so any bounce with
    // cos θ < 0.31 ends the path and the light it would have found is lost.
    const Furnace furnace{Color(0.8f), Color(1)};
    const Setup dim(make_furnace_scene(furnace),
                    rule(Termination::kMinThroughput, kSafetyDepthCap, Real(0.5)), indirect_rays_alone());
    const Estimate e = furnace_estimate(dim, 6000, 710);
    CHECK(furnace_radiance(furnace).y - e.mean > 8 * e.error);
}

TEST_CASE("Light sampling in the furnace: one bounce gives Le (1 + rho) where its samples are bounded",
          "[furnace][statistical][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch04.direct_light]"
          "[ex:ch04.lambert][ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch05.trace]") {
    // Camera rays from the centre to the middle of the back wall (|x|, |y| <= 0.5): every wall sample is at
    // least 0.5 away, so f Le cos θ cos θ_l A / d² is bounded and the error bars hold.
    for (Real rho : {0.25f, 0.7f}) {
        INFO("rho " << rho);
        const Furnace furnace{Color(rho), Color(2)};
        const Setup setup(make_furnace_scene(furnace), rule(Termination::kMaxDepth, 1));
        Pcg32 film(740, 0);
        RayCounts rays;
        std::uint64_t path = 0;
        const Estimate e = estimate(20000, [&] {
            const Vec2 u = film.next_vec2();
            const Ray ray{Vec3(0), glm::normalize(Vec3{u.x - 0.5f, u.y - 0.5f, -1})};
            Pcg32 rng = Pcg32::for_sample(1, path++, 741);
            return double(setup.tracer->radiance(ray, rng, rays).g);
        });
        CHECK(std::abs(e.mean - 2 * (1 + rho)) <= 4 * e.error);
        CHECK(rays[RayKind::kShadow] == 5u * 20000u);  // the five other walls, once each
        CHECK(rays[RayKind::kIndirect] == 0);          // depth 1: direct light only
    }
}

TEST_CASE("Emission is counted once: light sampling and indirect rays alone agree on the Cornell box",
          "[statistical][ex:ch02.quad_packet][ex:ch02.sphere_stable][ex:ch03.robust_offset]"
          "[ex:ch04.direct_light][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch04.uniform_hemisphere][ex:ch05.mirror_scatter][ex:ch05.termination][ex:ch05.trace]"
          "[ex:ch05.uniform_scatter]") {
    // With light sampling, an indirect ray that hits the lamp must not add its Le again; without it, indirect
    // rays must add it. Both estimate the same radiance, so their means agree within their error bars;
    // counting the lamp twice (or never) would add (or remove) the whole direct term of the back wall.
    const Scene scene = load_scene(scene_path("ch05_default.json"));
    const Setup sampled(scene, rule(Termination::kRussianRoulette, kSafetyDepthCap));
    const Setup hit(scene, rule(Termination::kRussianRoulette, kSafetyDepthCap), indirect_rays_alone());
    const Ray ray{{278, 278, -800}, glm::normalize(Vec3{278, 300, 555} - Vec3{278, 278, -800})};  // back wall
    auto run = [&](const Setup& setup, int n, std::uint64_t seed, RayCounts& rays) {
        std::uint64_t path = 0;
        return estimate(n, [&] {
            Pcg32 rng = Pcg32::for_sample(2, path++, seed);
            return double(setup.tracer->radiance(ray, rng, rays).g);
        });
    };
    RayCounts sampled_rays, hit_rays;
    const Estimate a = run(sampled, 20000, 750, sampled_rays);
    const Estimate b = run(hit, 100000, 751, hit_rays);
    CHECK(sampled_rays[RayKind::kShadow] > 0);
    CHECK(hit_rays[RayKind::kShadow] == 0);
    CHECK(b.mean > 0.2);  // the lamp is found by chance often enough for a meaningful comparison
    CHECK(std::abs(a.mean - b.mean) <= 4 * std::sqrt(a.error * a.error + b.error * b.error));
    // The direct term alone (depth 1) is a large part of it: double counting would show.
    RayCounts depth1_rays;
    const Setup direct_only(scene, rule(Termination::kMaxDepth, 1));
    const Estimate d = run(direct_only, 5000, 752, depth1_rays);
    CHECK(d.mean > 10 * (a.error + b.error));
}

TEST_CASE("An emissive plane, which light sampling cannot reach, is found by indirect rays",
          "[statistical][ex:ch02.plane][ex:ch03.robust_offset][ex:ch04.direct_light][ex:ch04.lambert]"
          "[ex:ch04.uniform_hemisphere][ex:ch05.termination][ex:ch05.trace][ex:ch05.uniform_scatter]") {
    // A floor of albedo 0.6 under an infinite emitting ceiling (Le = 2, facing down, black): L = ρ Le = 1.2.
    Scene scene;
    scene.materials = {diffuse(Color(0.6f)), diffuse(Color(0), Color(2))};
    scene.shapes.push_back(Shape{PlaneShape{{0, 0, 0}, {0, 1, 0}}, 0, "floor"});
    scene.shapes.push_back(Shape{PlaneShape{{0, 1, 0}, {0, -1, 0}}, 1, "ceiling"});
    scene.camera = CameraDesc{{0, 0.5f, 0}, {0, 0, 1}, {0, 1, 0}, 40};
    const Setup setup(scene, rule(Termination::kMaxDepth, 1));
    REQUIRE(setup.shading->lights().unsampled.size() == 1);
    Pcg32 rng(730, 0);
    RayCounts rays;
    const Ray down{{0, 0.5f, 0}, glm::normalize(Vec3{0.3f, -1, 0.2f})};
    const Estimate e = estimate(20000, [&] { return double(setup.tracer->radiance(down, rng, rays).g); });
    CHECK(std::abs(e.mean - 1.2) <= 4 * e.error);
    CHECK(rays[RayKind::kShadow] == 0);
}

// ---------------------------------------------------------------------------------------------------------
// Mirrors

TEST_CASE("Mirror reflection: angle out equals angle in, in the plane of incidence, weight R",
          "[mirror][ex:ch05.mirror_scatter]") {
    const MirrorBrdf chrome{Color(0.9f, 0.5f, 0.2f)};
    Pcg32 rng(800, 0);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 n = random_unit(rng);
        Vec3 wo = random_unit(rng);
        if (glm::dot(wo, n) < 0) wo = -wo;
        const auto s = mirror_scatter(chrome, wo, n);
        if (glm::dot(wo, n) < 1e-3f) continue;  // grazing: covered by its own test
        REQUIRE(s);
        REQUIRE(glm::length(s->wi) == Approx(1).epsilon(1e-6));
        REQUIRE(glm::dot(s->wi, n) == Approx(glm::dot(wo, n)).margin(1e-6));    // θ_out = θ_in
        REQUIRE(glm::dot(glm::cross(wo, n), s->wi) == Approx(0).margin(1e-6));  // coplanar with wo and n
        REQUIRE(glm::length(s->wi + wo - 2 * glm::dot(wo, n) * n) < 1e-5f);     // on the other side of n
        REQUIRE(s->weight == chrome.reflectance);
    }
    CHECK_FALSE(mirror_scatter(MirrorBrdf{Color(0)}, Vec3{0, 0, 1}, Vec3{0, 0, 1}));
}

TEST_CASE("A mirror shows the lamp it faces at R times its radiance, through one reflection ray",
          "[mirror][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch05.mirror_scatter]"
          "[ex:ch05.termination][ex:ch05.trace]") {
    // A mirror in the plane y = 0 facing up; a lamp (Le = 4, facing down) hangs where the reflection lands.
    const Color R(0.9f, 0.5f, 0.2f);
    Scene scene;
    scene.materials = {mirror(R), diffuse(Color(0), Color(4))};
    scene.shapes.push_back(quad({-5, 0, -5}, {0, 0, 10}, {10, 0, 0}, 0));  // normal +y
    scene.shapes.push_back(
        quad({1, 2, -1}, {2, 0, 0}, {0, 0, 2}, 1));  // normal −y, over x, z in [1,3]×[−1,1]
    const Setup setup(scene, rule(Termination::kRussianRoulette, kSafetyDepthCap));
    // From (−2, 2, 0) down to (0, 0, 0): the mirror image goes up to (2, 2, 0), the middle of the lamp.
    const Ray ray{{-2, 2, 0}, glm::normalize(Vec3{2, -2, 0})};
    Pcg32 rng(801, 0);
    RayCounts rays;
    const Color L = setup.tracer->radiance(ray, rng, rays);
    CHECK(L.r == Approx(4 * 0.9));
    CHECK(L.g == Approx(4 * 0.5));
    CHECK(L.b == Approx(4 * 0.2));
    CHECK(rays[RayKind::kReflection] == 1);
    CHECK(rays[RayKind::kShadow] == 0);  // a delta BRDF is never light-sampled
    CHECK(rays[RayKind::kIndirect] == 0);
    // The effect reflection off: the mirror is black.
    const Setup off(scene, rule(Termination::kRussianRoulette, kSafetyDepthCap),
                    simulating(EffectSet::all().without({Effect::kReflection})));
    RayCounts none;
    CHECK(off.tracer->radiance(ray, rng, none) == Color(0));
    CHECK(none[RayKind::kReflection] == 0);
}

TEST_CASE("A mirror facing a mirror terminates under every rule",
          "[mirror][stability][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch05.mirror_scatter]"
          "[ex:ch05.termination][ex:ch05.trace]") {
    // Two parallel mirrors 1 apart and a ray perpendicular to both: it would bounce forever.
    auto facing_mirrors = [](Real reflectance) {
        Scene scene;
        scene.materials = {mirror(Color(reflectance))};
        scene.shapes.push_back(quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, 0));
        scene.shapes.push_back(quad({-1, -1, 1}, {0, 2, 0}, {2, 0, 0}, 0));
        return scene;
    };
    const Ray ray{{0, 0, 0.5f}, {0, 0, 1}};
    // Perfect mirrors keep β = 1, so only the cap can end the path: exactly max_depth reflection rays.
    for (Termination t :
         {Termination::kMaxDepth, Termination::kMinThroughput, Termination::kRussianRoulette}) {
        for (int cap : {1, 8, 1000}) {
            INFO(to_string(t) << ", cap " << cap);
            const Setup setup(facing_mirrors(1), rule(t, cap));
            Pcg32 rng(900, 0);
            RayCounts rays;
            const Color L = setup.tracer->radiance(ray, rng, rays);
            CHECK(L == Color(0));
            CHECK(rays[RayKind::kReflection] == std::uint64_t(cap));
        }
    }
    // R = 0.95: the throughput rule stops once 0.95^k < 0.01, after k = ⌈ln 0.01 / ln 0.95⌉ = 90 bounces.
    const Setup dim(facing_mirrors(0.95f), rule(Termination::kMinThroughput, 1000));
    Pcg32 rng(901, 0);
    RayCounts rays;
    dim.tracer->radiance(ray, rng, rays);
    CHECK(rays[RayKind::kReflection] == 90);
    // Roulette: 3 sure bounces (β = 0.95³), then survival with q = 0.95³ once and q = 0.95 ever after (β is
    // rescaled to 1 on each survival): on average 3 + 0.95³ · 1 / (1 − 0.95) = 20.15 reflection rays, far
    // below the cap.
    const Setup roulette(facing_mirrors(0.95f), rule(Termination::kRussianRoulette, 1000));
    std::uint64_t path = 0;
    const Estimate bounces = estimate(4000, [&] {
        RayCounts one;
        Pcg32 r = Pcg32::for_sample(0, path++, 902);
        roulette.tracer->radiance(ray, r, one);
        return double(one[RayKind::kReflection]);
    });
    CHECK(std::abs(bounces.mean - (3 + 0.95 * 0.95 * 0.95 * 20)) <= 4 * bounces.error);
}

// ---------------------------------------------------------------------------------------------------------
// Hard cases

TEST_CASE("Grazing rays give finite radiance, never NaN",
          "[stability][ex:ch02.quad_packet][ex:ch02.sphere_stable][ex:ch03.robust_offset]"
          "[ex:ch04.direct_light][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch04.uniform_hemisphere][ex:ch05.mirror_scatter][ex:ch05.termination][ex:ch05.trace]"
          "[ex:ch05.uniform_scatter]") {
    // A lit room: a diffuse floor, a mirror wall and a lamp.
    Scene scene;
    scene.materials = {diffuse(Color(0.7f)), mirror(Color(0.95f)), diffuse(Color(0), Color(10))};
    scene.shapes.push_back(quad({-5, 0, 5}, {10, 0, 0}, {0, 0, -10}, 0));  // floor y = 0, normal +y
    scene.shapes.push_back(quad({5, 0, -5}, {0, 0, 10}, {0, 5, 0}, 1));    // mirror x = 5, normal −x
    scene.shapes.push_back(quad({-1, 3, -1}, {2, 0, 0}, {0, 0, 2}, 2));    // lamp, normal −y
    scene.shapes.push_back(Shape{SphereShape{{-2, 1, 0}, 1}, 0, "ball"});
    const Setup setup(scene, rule(Termination::kRussianRoulette, kSafetyDepthCap));
    std::vector<Ray> rays_to_try;
    for (double angle : {1e-2, 1e-4, 1e-6, 1e-8, 0.0}) {
        const Real s = Real(std::sin(angle)), c = Real(std::cos(angle));
        rays_to_try.push_back({{-4, 0.5f, 0.3f}, glm::normalize(Vec3{c, -s, 0})});  // down onto the floor
        rays_to_try.push_back({{-4, 0, 0.3f}, glm::normalize(Vec3{c, s, 0.1f})});   // along the floor itself
        rays_to_try.push_back({{4, 1, -4}, glm::normalize(Vec3{s, 0, c})});         // along the mirror
        rays_to_try.push_back({{-4, 2, 0}, glm::normalize(Vec3{c, 0, s})});         // tangent to the ball
    }
    Pcg32 rng(1000, 0);
    for (const Ray& ray : rays_to_try) {
        RayCounts rays;
        for (int i = 0; i < 300; ++i) {
            const Color L = setup.tracer->radiance(ray, rng, rays);
            REQUIRE(is_finite(L));
            REQUIRE(L.r >= 0);
        }
    }
    // A hemisphere direction in the tangent plane (u₁ = 0 gives z = 0) carries nothing; u just below 1 is
    // finite and unit. A mirror hit edge-on reflects nothing.
    const LambertBrdf lambert{Color(0.5f)};
    const Vec3 n{0, 1, 0}, wo = glm::normalize(Vec3{1, 1, 0});
    CHECK_FALSE(uniform_scatter(lambert, wo, n, Vec2(0, 0.3f)));
    const auto top = uniform_scatter(lambert, wo, n, Vec2(kOneMinusEpsilon, kOneMinusEpsilon));
    REQUIRE(top);
    CHECK(is_finite(top->weight));
    CHECK(glm::length(top->wi) == Approx(1));
    CHECK_FALSE(mirror_scatter(MirrorBrdf{Color(1)}, Vec3{1, 0, 0}, n));
    const auto skim = mirror_scatter(MirrorBrdf{Color(1)}, glm::normalize(Vec3{1, 1e-7f, 0}), n);
    if (skim) CHECK(glm::dot(skim->wi, n) > 0);
}

TEST_CASE("The uniform hemisphere weight of a Lambert surface has mean rho",
          "[statistical][ex:ch04.lambert][ex:ch04.uniform_hemisphere][ex:ch05.uniform_scatter]") {
    const LambertBrdf lambert{Color(0.7f)};
    Pcg32 rng(1100, 0);
    const Vec3 n = glm::normalize(Vec3{0.2f, -0.3f, -1});  // near −z, where frames are hardest
    const Vec3 wo = glm::normalize(n + Vec3{0.3f, 0, 0});
    const Estimate e = estimate(100000, [&] {
        const auto s = uniform_scatter(lambert, wo, n, rng.next_vec2());
        if (!s) return 0.0;
        REQUIRE(glm::dot(s->wi, n) > 0);
        REQUIRE(s->weight.g == Approx(2 * 0.7 * glm::dot(s->wi, n)).epsilon(1e-5));
        return double(s->weight.g);
    });
    CHECK(std::abs(e.mean - 0.7) <= 4 * e.error);
}

// ---------------------------------------------------------------------------------------------------------
// Renders

namespace {

// With the effects a run of chapter 05 simulates for the scene, unless `effects` says others.
RenderResult render_scene(const Scene& scene, TerminationSettings termination, int size, int spp, int threads,
                          std::optional<EffectSet> effects = std::nullopt) {
    const Setup setup(scene, termination,
                      effects ? std::optional<DirectOptions>(simulating(*effects)) : std::nullopt);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
    const RenderSettings settings{size, size, spp, 5, threads, ProgressStyle::kNone};
    return render_gi(*setup.tracer, camera, settings);
}

}  // namespace

TEST_CASE(
    "Ray counts follow the effects: without a mirror no reflection rays, without indirect no indirect rays",
    "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
    "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch04.direct_light][ex:ch04.lambert]"
    "[ex:ch04.sample_quad_light][ex:ch04.uniform_hemisphere][ex:ch05.mirror_scatter]"
    "[ex:ch05.termination][ex:ch05.trace][ex:ch05.uniform_scatter]") {
    const Scene cornell = load_scene(scene_path("ch05_default.json"));
    const TerminationSettings t = rule(Termination::kRussianRoulette, kSafetyDepthCap);
    const RenderResult all = render_scene(cornell, t, 24, 1, 1);
    CHECK(all.rays[RayKind::kReflection] > 0);
    CHECK(all.rays[RayKind::kIndirect] > 0);
    CHECK(all.rays[RayKind::kShadow] > 0);
    CHECK(all.rays[RayKind::kRefraction] == 0);

    Scene no_mirror = cornell;
    for (Material& m : no_mirror.materials) {
        if (m.type == "mirror") m = diffuse(Color(0.5f));
    }
    const RenderResult diffuse_only = render_scene(no_mirror, t, 24, 1, 1);
    CHECK(diffuse_only.rays[RayKind::kReflection] == 0);
    CHECK(diffuse_only.rays[RayKind::kIndirect] > 0);

    const EffectSet no_indirect = EffectSet::all().without(EffectSet{Effect::kIndirect});
    const RenderResult direct_only = render_scene(cornell, t, 24, 1, 1, no_indirect);
    CHECK(direct_only.rays[RayKind::kIndirect] == 0);
    CHECK(direct_only.rays[RayKind::kReflection] > 0);
    // Indirect light only adds: the room is brighter with it.
    CHECK(all.image.mean() > direct_only.image.mean() * 1.2);

    // Depth 1 is direct light only: the one indirect ray it could trace would add nothing, so none is traced.
    const RenderResult depth1 = render_scene(cornell, rule(Termination::kMaxDepth, 1), 24, 1, 1);
    CHECK(depth1.rays[RayKind::kIndirect] == 0);
    CHECK(depth1.rays[RayKind::kShadow] > 0);
}

TEST_CASE("The default scene renders finite, plausible and identical on 1 and 2 threads",
          "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch04.direct_light][ex:ch04.lambert]"
          "[ex:ch04.sample_quad_light][ex:ch04.uniform_hemisphere][ex:ch05.mirror_scatter]"
          "[ex:ch05.termination][ex:ch05.trace][ex:ch05.uniform_scatter]") {
    const Scene scene = load_scene(scene_path("ch05_default.json"));
    const TerminationSettings t = rule(Termination::kRussianRoulette, kSafetyDepthCap);
    const RenderResult one = render_scene(scene, t, 40, 2, 1);
    const RenderResult two = render_scene(scene, t, 40, 2, 2);
    CHECK(one.image.all_finite());
    CHECK(one.image.pixels() == two.image.pixels());
    CHECK(one.rays.count == two.rays.count);
    CHECK(one.image.mean() > 0.08);
    CHECK(one.image.mean() < 0.4);
    CHECK(one.rays[RayKind::kCamera] == 40u * 40u * 2u);
}

TEST_CASE("The depth cap: --max-depth, else the scene's max_depth, else the rule's own", "[termination]") {
    const auto resolved = [](std::vector<std::string> args, std::optional<int> scene_depth) {
        CLI::App app;
        TerminationFlags flags;
        add_termination_flags(app, flags);
        std::reverse(args.begin(), args.end());  // CLI11 reads a vector of arguments from its back
        app.parse(args);
        Scene scene;
        scene.max_depth = scene_depth;
        return flags.resolved(scene);
    };
    CHECK(resolved({}, std::nullopt).max_depth == kSafetyDepthCap);
    CHECK(resolved({"--termination", "depth"}, std::nullopt).max_depth == 8);
    CHECK(resolved({}, 3).max_depth == 3);
    CHECK(resolved({"--termination", "depth"}, 3).max_depth == 3);
    const TerminationSettings given = resolved({"--max-depth", "5"}, 3);
    CHECK(given.max_depth == 5);
    CHECK(given.rule == Termination::kRussianRoulette);
}
