// Chapter 12: path guiding. The equal-area map (a round trip, its Jacobian 4π), the directional quadtree
// (its sample against its pdf by chi-square, its pdf integrating to 1, refinement keeping the energy and the
// density), the spatial tree's splits, the one-sample mixture of a guided vertex (chi-square against its
// density, the density it reports), what a training path records, and the guided path tracer: unbiased in a
// white furnace, a closed box of emitters and on chapter 06's Cornell box, chapter 06's image to the bit
// without training, and the same image on 1 and 2 threads.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "04_direct_lighting/brdf.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "05_recursive_gi/gi_render.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "06_monte_carlo/render_paths.hpp"
#include "12_path_guiding/directional_quadtree.hpp"
#include "12_path_guiding/equal_area_map.hpp"
#include "12_path_guiding/guided_render.hpp"
#include "12_path_guiding/guided_vertex.hpp"
#include "12_path_guiding/guiding_field.hpp"
#include "12_path_guiding/radiance_recorder.hpp"
#include "12_path_guiding/spatial_tree.hpp"
#include "rt/core/random.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/scene_loader.hpp"
#include "support/block_means.hpp"
#include "support/chi_square.hpp"
#include "support/closed_box_scene.hpp"

using namespace rt;
using namespace rt::test;

namespace {

// Every chi-square test of this file (the quadtree, untrained and trained, and the guided vertex's mixture),
// each at the Šidák-corrected level of tests/support/chi_square.hpp.
constexpr int kChiSquareTests = 3;
const double kLevel = sidak_level(kChiSquareTests, 0.01);

// A quadtree trained on a lobe of light around `toward` (weight max(0, cos)^8 from uniform directions: the
// equal-area map of uniform points) in
// three rounds of record and refine: leaves several levels deep where the lobe is.
DirectionalQuadtree trained_tree(const Vec3& toward, int max_depth = 20) {
    DirectionalQuadtree tree;
    Pcg32 rng(5, 3);
    for (int round = 0; round < 3; ++round) {
        DirectionalQuadtree recording = tree.emptied();
        for (int i = 0; i < 100000; ++i) {
            const Vec3 w = equal_area_direction(rng.next_vec2());
            recording.record(w, Real(std::pow(std::max(0.0, double(glm::dot(w, toward))), 8)));
        }
        tree = recording.refined(0.01, max_depth);
    }
    return tree;
}

const Vec3 kLobe = glm::normalize(Vec3(1, 0.5f, 0.8f));

// A surface point at the origin facing +z, as a path's hit.
Hit hit_facing_up() {
    Hit hit;
    hit.t = 1;
    return hit;
}

// Chapter 06's paths on `scene` (the effects chapter 06 simulates for it), guided after `passes` training
// passes; `spatial` is the spatial tree's threshold c, `combination` what the image is made of.
GuidedRender render_guided_scene(const Scene& scene, int size, int spp, std::uint64_t seed, int threads,
                                 int passes, double spatial = 12000,
                                 PassCombination combination = PassCombination::kInverseVariance) {
    const EffectSet simulated = simulated_effects(scene, kRecursiveChapterEffects);
    const RenderScene prepared(scene, simulated);
    PathOptions options;
    options.simulated = simulated;
    const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
    const RenderSettings settings{size, size, spp, seed, threads, ProgressStyle::kNone};
    GuidedRenderOptions guided;
    guided.training_passes = passes;
    guided.field.spatial_threshold = spatial;
    guided.combination = combination;
    return render_guided(prepared, camera, settings, options, guided);
}

// Chapter 06's unguided paths on `scene`.
RenderResult render_unguided(const Scene& scene, int size, int spp, std::uint64_t seed, int threads) {
    const EffectSet simulated = simulated_effects(scene, kRecursiveChapterEffects);
    const RenderScene prepared(scene, simulated);
    PathOptions options;
    options.simulated = simulated;
    const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
    const RenderSettings settings{size, size, spp, seed, threads, ProgressStyle::kNone};
    return render_paths(tracer, make_pinhole_camera(scene.camera, size, size), settings);
}

// Chapter 06's white furnace: a diffuse sphere of albedo 0.5 under a uniform sky of radiance 1, which every
// pixel wholly on the sphere sees as 0.5.
Scene furnace_scene() {
    Scene scene;
    scene.file = "furnace";
    scene.camera = CameraDesc{{0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 40};
    Material m;
    m.name = "diffuse";
    m.albedo = Color(0.5f);
    scene.materials.push_back(m);
    scene.shapes.push_back(Shape{SphereShape{{0, 0, 0}, 1}, 0, "shapes[0]"});
    scene.environment = EnvironmentLight{Color(1)};
    return scene;
}

}  // namespace

TEST_CASE("The equal-area map: point(direction(p)) is p, and it covers 4 pi steradians per unit of area",
          "[guiding]") {
    Pcg32 rng(1, 1);
    for (int i = 0; i < 10000; ++i) {
        const Vec2 p = rng.next_vec2();
        const Vec3 w = equal_area_direction(p);
        REQUIRE(glm::length(w) == Approx(1).margin(1e-5));
        const Vec2 back = equal_area_point(w);
        REQUIRE(back.x == Approx(p.x).margin(1e-5));
        REQUIRE(back.y == Approx(p.y).margin(2e-5));
    }
    // |∂w/∂u × ∂w/∂v| by central differences (double) at points away from the poles.
    for (int i = 0; i < 1000; ++i) {
        const Vec2d p(0.05 + 0.9 * double(rng.next_real()), double(rng.next_real()));
        const auto direction = [](double u, double v) {
            const double z = 2 * u - 1, r = std::sqrt(1 - z * z), phi = 2 * std::numbers::pi * v;
            return Vec3d(r * std::cos(phi), r * std::sin(phi), z);
        };
        const double h = 1e-6;
        const Vec3d du = (direction(p.x + h, p.y) - direction(p.x - h, p.y)) / (2 * h);
        const Vec3d dv = (direction(p.x, p.y + h) - direction(p.x, p.y - h)) / (2 * h);
        REQUIRE(glm::length(glm::cross(du, dv)) == Approx(double(kEqualAreaJacobian)).epsilon(1e-5));
        // The course's map is the same function.
        const Vec3 w = equal_area_direction(Vec2(p));
        REQUIRE(double(w.z) == Approx(direction(p.x, p.y).z).margin(1e-5));
    }
    CHECK(kEqualAreaJacobian == Approx(4 * std::numbers::pi));
}

TEST_CASE("The quadtree's pdf integrates to 1 over the square, untrained and trained", "[guiding]") {
    for (const DirectionalQuadtree& tree : {DirectionalQuadtree(), trained_tree(kLobe, 9)}) {
        // Leaves no deeper than 9 levels: the midpoints of a 1024 × 1024 grid hit each leaf its area's share.
        REQUIRE(tree.depth() <= 9);
        double sum = 0;
        constexpr int kSide = 1024;
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x)
                sum += double(tree.pdf_square(Vec2((Real(x) + 0.5f) / kSide, (Real(y) + 0.5f) / kSide)));
        CHECK(sum / (kSide * kSide) == Approx(1).epsilon(1e-5));
    }
    CHECK(trained_tree(kLobe, 9).depth() > 4);
}

TEST_CASE("The quadtree's sample fits its pdf by chi-square over the sphere, untrained and trained",
          "[guiding][statistical]") {
    const DirectionalQuadtree uniform;
    const DirectionalQuadtree trained = trained_tree(kLobe);
    INFO("trained: " << trained.node_count() << " nodes, depth " << trained.depth());
    REQUIRE(trained.depth() > 4);
    std::uint64_t seed = 1201;
    for (const DirectionalQuadtree* tree : {&uniform, &trained}) {
        const ChiSquare r = test_directions(
            [&](Vec2 u) {
                const DirectionSample s = tree->sample(u);
                return Drawn{s.w, double(s.pdf)};
            },
            [&](const Vec3& w) { return double(tree->pdf(w)); }, seed++);
        require_fit(r, kLevel);
    }
    // The pdf a sample reports is the pdf of its direction, and the lobe is where the density is.
    Pcg32 rng(7, 7);
    for (int i = 0; i < 10000; ++i) {
        const DirectionSample s = trained.sample(rng.next_vec2());
        REQUIRE(s.pdf == Approx(trained.pdf(s.w)).epsilon(1e-4));
    }
    CHECK(trained.pdf(kLobe) > 10 * trained.pdf(-kLobe));
}

TEST_CASE("Refinement keeps the energy to the unit and the density but for rounding, and empties to zero",
          "[guiding]") {
    DirectionalQuadtree tree;
    Pcg32 rng(9, 9);
    for (int i = 0; i < 50000; ++i) {
        const Vec3 w = equal_area_direction(rng.next_vec2());
        tree.record(w, Real(std::pow(std::max(0.0, double(glm::dot(w, kLobe))), 4)) * 3);
    }
    const std::uint64_t energy = tree.energy_units();
    REQUIRE(energy > 0);
    for (int round = 0; round < 4; ++round) {
        const DirectionalQuadtree refined = tree.refined(0.01, 20);
        CHECK(refined.energy_units() == energy);
        for (int i = 0; i < 1000; ++i) {
            const Vec3 w = equal_area_direction(rng.next_vec2());
            REQUIRE(refined.pdf(w) == Approx(tree.pdf(w)).epsilon(1e-3).margin(1e-6));
        }
        tree = refined;
    }
    CHECK(tree.node_count() > 1);
    CHECK(tree.emptied().energy_units() == 0);
    CHECK(tree.emptied().node_count() == tree.node_count());
    // Weights that are not numbers, or negative, are not recorded.
    DirectionalQuadtree other;
    other.record(kLobe, -1);
    other.record(kLobe, std::numeric_limits<Real>::quiet_NaN());
    other.record(kLobe, kInfinity);
    CHECK(other.energy_units() == 0);
}

TEST_CASE("The spatial tree splits a leaf past the threshold along alternating axes, its halves numbered",
          "[guiding]") {
    SpatialTree tree(Aabb{Vec3(0), Vec3(8)});
    // 100 vertices in the corner near the origin, 1 elsewhere.
    for (int i = 0; i < 100; ++i) tree.count(tree.leaf_of(Vec3(0.5f)));
    tree.count(tree.leaf_of(Vec3(7)));
    const std::vector<std::uint32_t> origin = tree.split(30);
    // 101 > 30: cut in x (50, 51 after halving); each half cut in y (25, 25 / 25, 26): four leaves.
    REQUIRE(tree.leaf_count() == 4);
    CHECK(origin == std::vector<std::uint32_t>{0, 0, 0, 0});
    const std::uint32_t low = tree.leaf_of(Vec3(0.5f)), high = tree.leaf_of(Vec3(7));
    CHECK(low != high);
    CHECK(tree.leaf_of(Vec3(0.5f, 7, 0.5f)) != low);   // y halves
    CHECK(tree.leaf_of(Vec3(0.5f, 0.5f, 7)) == low);   // not yet z
    CHECK(tree.leaf_of(Vec3(-5)) == low);              // outside: the nearest leaf
    CHECK(tree.samples(low) == 0);                     // counts start again
    CHECK(tree.split(30) == std::vector<std::uint32_t>{0, 1, 2, 3});
}

TEST_CASE("The stochastic box filter lands records near a leaf's border in the neighbouring leaf too",
          "[guiding]") {
    for (const SpatialFilter filter : {SpatialFilter::kNearest, SpatialFilter::kBox}) {
        GuidingSettings settings;
        settings.spatial_threshold = 30;
        settings.spatial_filter = filter;
        GuidingField field(Aabb{Vec3(0), Vec3(8)}, settings);
        // Pass 1 splits the box into four leaves, as in the test above: [0, 4] × [0, 4] × [0, 8] holds p.
        for (int i = 0; i < 100; ++i) field.record(Vec3(0.5f), kLobe, 1);
        field.record(Vec3(7), kLobe, 1);
        field.finish_pass();
        REQUIRE(field.leaf_count() == 4);
        // Pass 2 records only at p, 0.1 from the border x = 4 (each record's direction its own).
        const Vec3 p(3.9f, 1, 1);
        for (int i = 0; i < 200; ++i)
            field.record(p, glm::normalize(Vec3(Real(i % 17) - 8, Real(i % 13) - 6, 3)), 1);
        field.finish_pass();
        CAPTURE(to_string(filter));
        CHECK(field.guide_at(p) != nullptr);
        // The leaf beyond the border learned only from the box filter's records.
        CHECK((field.guide_at(Vec3(5, 1, 1)) != nullptr) == (filter == SpatialFilter::kBox));
    }
}

TEST_CASE("A guided vertex's one-sample mixture fits its density by chi-square, and reports that density",
          "[guiding][statistical][ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch12.one_sample_mis]") {
    const DirectionalQuadtree guide = trained_tree(kLobe);
    const LambertBrdf lambert(Color(0.7f));
    const Hit hit = hit_facing_up();
    const RayOffset offset;
    const Vec3 wo = glm::normalize(Vec3(0.3f, -0.2f, 1));
    const BsdfVertex bsdf(hit, wo, lambert, SamplingStrategy::kMis, true, offset);
    // α = 0.3: a mixture whose choice is the wrong way round draws another density. The lobe lies partly
    // below the surface: the guide is folded onto the hemisphere above it.
    REQUIRE(guide.pdf(Vec3(0, 0, -1)) > 0);
    const GuidedVertex vertex(bsdf, false, &guide, 0.3f);
    Pcg32 rng(31, 5);
    const ChiSquare r = test_directions(
        [&](Vec2) {
            const auto c = vertex.sample(SampleStream(rng));
            return c ? Drawn{c->sample.wi, double(c->sample.pdf)} : Drawn{Vec3(0, 0, 1), 0, true};
        },
        [&](const Vec3& w) { return double(vertex.pdf(w)); }, 1203);
    require_fit(r, kLevel);
    CHECK(r.lost == 0);
    Pcg32 check(32, 5);
    for (int i = 0; i < 10000; ++i) {
        const auto c = vertex.sample(SampleStream(check));
        REQUIRE(c);
        const Vec3& wi = c->sample.wi;
        const Vec3 mirrored(wi.x, wi.y, -wi.z);
        REQUIRE(vertex.guide_pdf(wi) == Approx(guide.pdf(wi) + guide.pdf(mirrored)).epsilon(1e-5));
        REQUIRE(c->sample.pdf ==
                Approx(0.3 * vertex.guide_pdf(wi) + 0.7 * lambert.pdf(wo, wi, hit.shading_normal)).epsilon(1e-4));
        REQUIRE(c->sample.f == lambert.eval(wo, wi, hit.shading_normal));
        REQUIRE(c->cos_i == Approx(wi.z).epsilon(1e-5));
    }
    // A surface that transmits takes the guide over the whole sphere.
    const GuidedVertex through(bsdf, true, &guide, 0.3f);
    CHECK(through.guide_pdf(Vec3(0, 0, -1)) == guide.pdf(Vec3(0, 0, -1)));
    CHECK(vertex.guide_pdf(Vec3(0, 0, -1)) == 0);
}

TEST_CASE("A training path records, at each non-delta vertex, what scattered light arrived along wi over its density",
          "[guiding][ex:ch12.incident_radiance]") {
    GuidingSettings settings;
    settings.spatial_threshold = 1e9;
    GuidingField field(Aabb{Vec3(-1), Vec3(1)}, settings);
    PathState path;
    RadianceRecorder recorder(field, path);
    Hit first = hit_facing_up(), second = hit_facing_up(), mirror = hit_facing_up(), third = hit_facing_up();
    second.point = Vec3(0.5f, 0, 0);
    mirror.point = Vec3(0, 0.5f, 0);
    third.point = Vec3(0, 0, 0.5f);
    const Vec3 up(0, 0, 1), side(1, 0, 0);
    // Vertex 1: its next-event estimate gave 0.1; it draws up with pdf 0.5, f 0.25, cos 1: β after it 0.5.
    path.L = Color(0.1f);
    CHECK(recorder.reached(first, BsdfFlags{}, 0));
    recorder.sampled(Color(1), BsdfSample{up, Color(0.25f), 0.5f}, 1);
    // The mirror emits 0.3, which vertex 1's next-event estimate is for: not vertex 1's to learn. The mirror
    // is not recorded, but what it reflects is light scattered toward vertex 1.
    path.L += Color(0.3f);
    recorder.reached(mirror, BsdfFlags{.delta = true}, 1);
    recorder.sampled(Color(0.5f), BsdfSample{-up, Color(1), 1, true}, 1);
    path.L += Color(0.2f);
    // Vertex 2: draws `side` with pdf 0.25, f (0.2, 0.4, 0), cos 0.5 from β 0.5: β after it (0.2, 0.4, 0).
    recorder.reached(second, BsdfFlags{}, 1);
    recorder.sampled(Color(0.5f), BsdfSample{side, Color(0.2f, 0.4f, 0), 0.25f}, 0.5f);
    // Vertex 3 emits (0.1, 0.1, 0.5) and its next-event estimate gives (0.05, 0.1, 0.3); it draws nothing.
    path.L += Color(0.1f, 0.1f, 0.5f);
    recorder.reached(third, BsdfFlags{}, 2);
    path.L += Color(0.05f, 0.1f, 0.3f);
    recorder.record();
    field.finish_pass();
    // L = (0.75, 0.8, 1.4). Vertex 1: the mean of (L − 0.4) / 0.5 = (0.7, 0.8, 2) over pdf 0.5: 7 / 3.
    // Vertex 2: the mean of 0.05 / 0.2 and 0.1 / 0.4 (the blue channel carries nothing) over pdf 0.25: 1.
    const DirectionalQuadtree* guide = field.guide_at(Vec3(0));
    REQUIRE(guide != nullptr);
    CHECK(guide->energy() == Approx(7.0 / 3 + 1).margin(3 * DirectionalQuadtree::kEnergyUnit));
    // It learned light from up and from the side, none from below.
    CHECK(guide->pdf(up) > guide->pdf(-up));
    CHECK(guide->pdf(side) > guide->pdf(-up));
}

TEST_CASE("Without training the guided render is chapter 06's image to the bit",
          "[guiding][render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch04.uniform_hemisphere][ex:ch04.uniform_hemisphere_pdf][ex:ch05.termination]"
          "[ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    const Scene scene = load_scene(scene_path("ch06_default.json"));
    const GuidedRender guided = render_guided_scene(scene, 24, 4, 5, 2, 0);
    const RenderResult unguided = render_unguided(scene, 24, 4, 5, 2);
    CHECK(guided.result.image.pixels() == unguided.image.pixels());
    CHECK(guided.passes.empty());
}

TEST_CASE("Guided paths keep the white furnace (unguided: nothing scattered to learn) and the closed box's L = 1",
          "[guiding][render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere]"
          "[ex:ch04.lambert][ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight]"
          "[ex:ch06.path_tracer][ex:ch12.incident_radiance][ex:ch12.one_sample_mis]") {
    const Scene furnace = furnace_scene();
    const int size = 32;
    // The image is the last render's (every pass's image is chapter 06's, but weighted they are not its image).
    const GuidedRender guided = render_guided_scene(furnace, size, 16, 1, 2, 3, 12000, PassCombination::kLast);
    const RenderResult& image = guided.result;
    REQUIRE(image.image.all_finite());
    // A convex sphere under the sky receives only the sky's light, which next-event estimation finds: no
    // scattered light arrives, the guide learns nothing and the image is chapter 06's.
    CHECK(image.image.pixels() == render_unguided(furnace, size, 16, 1, 2).image.pixels());
    const PinholeCamera camera = make_pinhole_camera(furnace.camera, size, size);
    double sum = 0, pixels = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            // Pixels whose four corners' rays hit the unit sphere: wholly on it.
            bool inside = true;
            for (Real dx : {0.0f, 1.0f})
                for (Real dy : {0.0f, 1.0f}) {
                    const Ray r = camera_ray(camera, Real(x) + dx, Real(y) + dy);
                    const Real b = glm::dot(r.origin, r.direction);
                    inside = inside && (b * b - (glm::dot(r.origin, r.origin) - 1) > 0);
                }
            if (!inside) continue;
            sum += double(image.image.at(x, y).g);
            ++pixels;
        }
    REQUIRE(pixels > 200);
    CHECK(sum / pixels == Approx(0.5).epsilon(0.01));
    const GuidedRender box = render_guided_scene(test::closed_box_scene(), 8, 64, 5, 2, 3);
    REQUIRE(box.result.image.all_finite());
    // The walls light each other: the guide learned, and drew some continuations.
    CHECK(box.result.image.pixels() != render_unguided(test::closed_box_scene(), 8, 64, 5, 2).image.pixels());
    CHECK(box.result.image.mean() == Approx(1).epsilon(0.03));
}

TEST_CASE(
    "Passes combined by inverse variance: each image weighted by 1 / its variance, unmeasured ones left out",
    "[guiding]") {
    const auto filled = [](Real value) {
        Image image(2, 1);
        for (Color& c : image.pixels()) c = Color(value);
        return image;
    };
    const std::vector<Image> images{filled(1), filled(4), filled(100)};
    // Weights 1 and 1/3; the third image, of variance 0, is not measured: (1 + 4 / 3) / (1 + 1 / 3) = 1.75.
    const Image combined = combined_by_variance(images, {1, 3, 0});
    for (const Color& c : combined.pixels()) CHECK(double(c.g) == Approx(1.75).epsilon(1e-6));
    CHECK(combined_by_variance(images, {0, 0, 0}).pixels() == images.back().pixels());
}

TEST_CASE(
    "Combined by inverse variance, the guided closed box keeps L = 1 and each pass of 2+ spp has a variance",
    "[guiding][render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
    "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere]"
    "[ex:ch04.lambert][ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight]"
    "[ex:ch06.path_tracer][ex:ch12.incident_radiance][ex:ch12.one_sample_mis]") {
    const GuidedRender box = render_guided_scene(test::closed_box_scene(), 8, 64, 5, 2, 3, 12000,
                                                 PassCombination::kInverseVariance);
    REQUIRE(box.passes.size() == 3);
    CHECK(box.passes[0].variance == 0);  // one sample per pixel: no variance to measure
    CHECK(box.passes[1].variance > 0);
    CHECK(box.passes[2].variance > 0);
    REQUIRE(box.result.image.all_finite());
    const GuidedRender last =
        render_guided_scene(test::closed_box_scene(), 8, 64, 5, 2, 3, 12000, PassCombination::kLast);
    CHECK(box.result.image.pixels() != last.result.image.pixels());
    CHECK(box.result.image.mean() == Approx(1).epsilon(0.03));
}

TEST_CASE("Guided paths converge to chapter 06's image on its Cornell box",
          "[guiding][render][statistical][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch04.uniform_hemisphere][ex:ch04.uniform_hemisphere_pdf][ex:ch05.termination]"
          "[ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch12.incident_radiance][ex:ch12.one_sample_mis]") {
    // Chapter 06's test of its strategies: the image in 2×2 blocks, each block's mean over kRuns independent
    // renders with its standard error; guided against unguided within 4.5 σ.
    const Scene scene = load_scene(scene_path("ch06_default.json"));
    constexpr int kSize = 16, kSpp = 16, kRuns = 8;
    auto blocks_of = [&](bool guided) {
        return test::block_means(kSize, kRuns, [&](std::uint64_t seed) {
            const Image image = guided ? render_guided_scene(scene, kSize, kSpp, seed, 2, 3, 500).result.image
                                       : render_unguided(scene, kSize, kSpp, seed, 2).image;
            REQUIRE(image.all_finite());
            return image;
        });
    };
    const test::BlockMeans guided = blocks_of(true), unguided = blocks_of(false);
    for (int b = 0; b < 4; ++b) {
        const double sigma =
            std::sqrt(guided.error[b] * guided.error[b] + unguided.error[b] * unguided.error[b]);
        INFO("block " << b << ": guided " << guided.mean[b] << " +- " << guided.error[b] << ", unguided "
                      << unguided.mean[b] << " +- " << unguided.error[b]);
        CHECK(std::abs(guided.mean[b] - unguided.mean[b]) <= 4.5 * sigma);
        CHECK(guided.error[b] > 0);
    }
}

TEST_CASE("A guided render is the same image on 1 and 2 threads, its space split and its trees counted",
          "[guiding][render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
          "[ex:ch04.uniform_hemisphere][ex:ch04.uniform_hemisphere_pdf][ex:ch05.termination]"
          "[ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch12.incident_radiance][ex:ch12.one_sample_mis]") {
    const Scene scene = load_scene(scene_path("ch06_default.json"));
    const GuidedRender one = render_guided_scene(scene, 24, 4, 5, 1, 4, 200);
    const GuidedRender two = render_guided_scene(scene, 24, 4, 5, 2, 4, 200);
    CHECK(one.result.image.pixels() == two.result.image.pixels());
    REQUIRE(one.passes.size() == 4);
    CHECK(one.passes.back().leaves > 8);
    CHECK(one.passes.back().leaves == two.passes.back().leaves);
    CHECK(one.bytes == two.bytes);
    CHECK(one.bytes > one.passes.back().leaves * sizeof(DirectionalQuadtree));
    // Every pass traced its camera rays, and the result counts them with the image's.
    std::uint64_t camera = 24 * 24 * 4;
    for (const TrainingPass& p : one.passes) camera += p.rays[RayKind::kCamera];
    CHECK(one.result.rays[RayKind::kCamera] == camera);
    CHECK(one.passes[2].rays[RayKind::kCamera] == 24u * 24u * 4u);
    CHECK(one.result.image.pixels() != render_unguided(scene, 24, 4, 5, 1).image.pixels());
}
