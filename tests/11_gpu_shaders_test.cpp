// Chapter 11: the path tracer as a shader. The shader's random numbers against the C++ generator (bit for
// bit), its intersections against chapter 02's on the hard cases of chapter 02's [stability] tests, and its
// images against chapter 07's CPU renderer. Every test here needs OpenGL: without a usable context it prints
// why and exits 77, which CTest reports as skipped (SKIP_RETURN_CODE).
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "02_intersection/mesh_generator.hpp"
#include "02_intersection/world.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "gl_context.hpp"
#include "gpu_render.hpp"
#include "random_unit.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/core/random.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/scene_loader.hpp"
#include "shader_probe.hpp"

using namespace rt;

// Every test here compiles the shaders, so it depends on their exercises (a stub is an #error).
#define SHADER_EXERCISES "[ex:ch11.bvh_traversal][ex:ch11.next_real][ex:ch11.pcg32]"

namespace {

constexpr int kSkipped = 77;

// The one context of this test process, or exit 77 (skipped) saying why there is none.
const GlContext& gl() {
    static std::optional<GlContext> context;
    if (!context) {
        try {
            context.emplace();
        } catch (const GlUnavailable& e) {
            std::printf("skipped: %s\n", e.what());
            std::fflush(stdout);
            std::exit(kSkipped);
        }
    }
    return *context;
}

Scene scene_of(std::vector<Shape> shapes) {
    Scene scene;
    scene.materials.push_back(Material{});
    scene.shapes = std::move(shapes);
    return scene;
}

GpuScene flattened(const Scene& scene) {
    const RenderScene prepared(scene, EffectSet::all());
    return flatten_scene(scene, prepared.materials, prepared.lights, LightPicker(prepared.lights));
}

// How many float steps apart a and b are (both finite, same sign).
std::int64_t ulps_apart(float a, float b) {
    return std::abs(std::int64_t(std::bit_cast<std::int32_t>(a)) -
                    std::int64_t(std::bit_cast<std::int32_t>(b)));
}

// The GPU's nearest hits against chapter 02's World on the same rays: the same hit or miss, the same
// primitive, and t within `max_ulps`. Returns the largest distance in ulps.
std::int64_t check_against_world(const Scene& scene, const std::vector<Ray>& rays, std::int64_t max_ulps) {
    const World world(scene);
    const ShaderProbe probe(gl(), flattened(scene));
    const std::vector<ProbeHit> gpu = probe.nearest_hits(rays, kInfinity);
    std::int64_t largest = 0;
    std::uint64_t hit_mismatches = 0, primitive_mismatches = 0, ties = 0, far = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const auto cpu = world.intersect(rays[i]);
        if (bool(cpu) != gpu[i].hit) {
            ++hit_mismatches;
            continue;
        }
        if (!cpu) continue;
        const std::int64_t apart = ulps_apart(float(cpu->t), gpu[i].t);
        // Where triangles meet, two primitives can be hit at the same t: both are the nearest hit, and which
        // one a traversal reports depends on the order it visits them (chapter 02's 4-wide tree and the
        // shader's binary one visit in different orders). A different primitive at a different t is a miss.
        if (cpu->primitive != gpu[i].primitive) {
            if (apart == 0)
                ++ties;
            else
                ++primitive_mismatches;
        }
        largest = std::max(largest, apart);
        if (apart > max_ulps) ++far;
    }
    CHECK(hit_mismatches == 0);
    CHECK(primitive_mismatches == 0);
    CHECK(far == 0);
    if (ties > 0) WARN(ties << " rays met two primitives at the same t (a tie where triangles meet)");
    return largest;
}

}  // namespace

TEST_CASE("An environment image is not in the shaders: a note says so, and its average radiance is shaded") {
    Scene scene = scene_of({Shape{SphereShape{{0, 0, 0}, 1}, 0, "shapes[0]"}});
    EnvironmentLight sky(Color(0.25f, 0.5f, 1));
    auto image = std::make_shared<Image>(4, 2);
    sky.image = image;
    sky.image_file = "sky.hdr";
    scene.environment = sky;
    const GpuScene gpu = flattened(scene);
    REQUIRE(gpu.environment.has_value());
    CHECK(*gpu.environment == Color(0.25f, 0.5f, 1));
    REQUIRE(gpu.notes.size() == 1);
    CHECK(gpu.notes[0].rfind("environment image sky.hdr: not in the shaders;", 0) == 0);
    scene.environment = EnvironmentLight(Color(1));
    CHECK(flattened(scene).notes.empty());
}

TEST_CASE("A BSDF the shaders do not know is refused with one line (exit 2) and no logic error") {
    // A chapter's own BSDF class, which chapter 11 has no exporter for.
    class Unknown final : public Bsdf {
      public:
        Unknown() : Bsdf({.diffuse = true}) {}
        Color eval(const Vec3&, const Vec3&, const Vec3&) const override { return Color(0); }
        BsdfSample sample(const Vec3&, const Vec3&, Vec2, Real) const override { return {}; }
        Real pdf(const Vec3&, const Vec3&, const Vec3&) const override { return 0; }
    };
    Scene scene = scene_of({Shape{SphereShape{{0, 0, 0}, 1}, 0, "shapes[0]"}});
    scene.materials[0].name = "odd";
    MaterialHooks hooks = refraction_materials();
    hooks.models["diffuse"].bsdf = [](const Material&, bool, BsdfAtHit& at) -> const Bsdf& {
        return at.emplace<Unknown>();
    };
    const RenderScene prepared(scene, EffectSet::all(), hooks);
    CHECK_THROWS_MATCHES(
        flatten_scene(scene, prepared.materials, prepared.lights, LightPicker(prepared.lights)), InputError,
        Catch::Message("diffuse material 'odd': its BSDF is not in the shaders (the chapters "
                       "before 11 render it)"));
}

TEST_CASE("Chapter 07's coated diffuse is not in the shaders: refused with one line (exit 2)") {
    Scene scene = scene_of({Shape{SphereShape{{0, 0, 0}, 1}, 0, "shapes[0]"}});
    scene.materials[0].name = "plastic";
    scene.materials[0].type = "coateddiffuse";
    const RenderScene prepared(scene, EffectSet::all(), refraction_materials());
    CHECK_THROWS_MATCHES(
        flatten_scene(scene, prepared.materials, prepared.lights, LightPicker(prepared.lights)), InputError,
        Catch::Message("coateddiffuse material 'plastic': its BSDF is not in the shaders (the chapters "
                       "before 11 render it)"));
}

TEST_CASE("The shader's PCG32 draws the C++ generator's numbers bit for bit",
          "[gpu]" SHADER_EXERCISES "[random]") {
    std::vector<ShaderProbe::Query> queries;
    Pcg32 pick(99, 1);
    for (int i = 0; i < 2000; ++i) {
        const std::uint64_t pixel = (std::uint64_t(pick.next_uint()) << (i % 33)) ^ pick.next_uint();
        queries.push_back({pixel, std::uint64_t(pick.next_uint() >> (i % 32))});
    }
    queries.push_back({0, 0});
    queries.push_back({~std::uint64_t(0), (1u << 20) - 1});
    const ShaderProbe probe(gl(), flattened(scene_of({})));
    for (const std::uint64_t seed :
         {std::uint64_t(0), std::uint64_t(1), std::uint64_t(0x8000000000000005ull)}) {
        const std::vector<ProbeRandom> gpu = probe.random_numbers(queries, seed);
        std::size_t words_differ = 0, reals_differ = 0, outside = 0, inexact = 0, odd = 0;
        for (std::size_t i = 0; i < queries.size(); ++i) {
            Pcg32 cpu = Pcg32::for_sample(queries[i].pixel, queries[i].sample, seed);
            for (int k = 0; k < 4; ++k)
                words_differ += cpu.next_uint() != gpu[i].words[std::size_t(k)] ? 1 : 0;
            for (int k = 0; k < 4; ++k) {
                const float expected = float(cpu.next_real());
                const float real = gpu[i].reals[std::size_t(k)];
                reals_differ += std::bit_cast<std::uint32_t>(expected) != std::bit_cast<std::uint32_t>(real) ? 1 : 0;
                // The properties every right answer has: in [0, 1), a whole number of 2^-24 (exact), and all 24
                // bits used (about half the numbers odd multiples of 2^-24).
                const double scaled = std::ldexp(double(real), 24);
                outside += real >= 0 && real < 1 ? 0 : 1;
                inexact += scaled == std::floor(scaled) ? 0 : 1;
                odd += std::fmod(scaled, 2.0) == 1.0 ? 1 : 0;
            }
        }
        const std::size_t reals = 4 * queries.size();
        INFO("seed " << seed << ", " << reals << " numbers");
        CHECK(words_differ == 0);
        const auto check_none = [](std::size_t count, const char* kind) {
            INFO(count << " numbers " << kind);
            CHECK(count == 0);
        };
        check_none(outside, "outside [0, 1)");
        check_none(inexact, "not exact (rounded: more bits than a float holds)");
        {
            INFO(odd << " odd multiples of 2^-24: fewer than 24 bits kept");
            CHECK(odd > reals / 4);
        }
        check_none(reals_differ, "differ from the C++ numbers");
    }
}

TEST_CASE("Shader rays from inside a closed mesh never escape, and meet what chapter 02 meets",
          "[gpu]" SHADER_EXERCISES "[stability][ex:ch02.slab_test][ex:ch02.slab_widening]"
          "[ex:ch02.wide_bvh_traversal]") {
    MeshShape mesh = make_icosphere(3);  // 1280 triangles
    jitter_radii(mesh, Real(0.05), 11);
    for (Vec3& p : mesh.positions) p = p * Real(3.7) + Vec3{10.3f, -5.1f, 2.9f};
    const Vec3 centre{10.3f, -5.1f, 2.9f};
    std::vector<Ray> rays;
    // Aimed exactly at every vertex and at 1/4, 2/4, 3/4 of every edge, where triangles meet; then random.
    for (const Vec3& p : mesh.positions) rays.push_back({centre, glm::normalize(p - centre)});
    for (const auto& t : mesh.triangles) {
        for (int e = 0; e < 3; ++e) {
            const Vec3 a = mesh.positions[t[std::size_t(e)]], b = mesh.positions[t[std::size_t((e + 1) % 3)]];
            for (int k = 1; k < 4; ++k)
                rays.push_back({centre, glm::normalize(a + (Real(k) / 4) * (b - a) - centre)});
        }
    }
    Pcg32 rng(5, 5);
    while (rays.size() < 20000) rays.push_back({centre, random_unit(rng)});
    const Scene scene = scene_of({Shape{mesh, 0, "mesh"}});
    const ShaderProbe probe(gl(), flattened(scene));
    std::size_t escaped = 0;
    for (const ProbeHit& h : probe.nearest_hits(rays, kInfinity)) escaped += h.hit ? 0 : 1;
    CHECK(escaped == 0);
    const std::int64_t largest = check_against_world(scene, rays, 4);
    WARN("closed mesh: t of the shader and of chapter 02 at most " << largest << " ulps apart");
}

TEST_CASE("Shader rays through a shared diagonal always hit one of its triangles",
          "[gpu]" SHADER_EXERCISES "[stability][ex:ch02.triangle_watertight]") {
    Pcg32 rng(17, 3);
    std::vector<Ray> rays;
    auto random_point = [&] {
        return Vec3{rng.next_real(), rng.next_real(), rng.next_real()} * Real(20) - Real(10);
    };
    // One quad split along p0–p2 per scene, as chapter 02's test; rays aimed exactly at the diagonal.
    std::size_t misses = 0, total = 0;
    for (int quad = 0; quad < 20; ++quad) {
        const Vec3 p0 = random_point(), p2 = random_point(), side = random_point();
        const Vec3 p1 = p0 + (p2 - p0) * Real(0.5) + side * Real(0.3),
                   p3 = p0 + (p2 - p0) * Real(0.5) - side * Real(0.3);
        const Vec3 normal = glm::cross(p1 - p0, p2 - p0);
        if (glm::length(normal) < Real(1e-3)) continue;
        const Scene scene = scene_of(
            {Shape{TriangleShape{{p0, p1, p2}}, 0, "a"}, Shape{TriangleShape{{p0, p2, p3}}, 0, "b"}});
        std::vector<Ray> quad_rays;
        for (int i = 0; i < 200; ++i) {
            const Vec3 target = p0 + rng.next_real() * (p2 - p0);
            const Vec3 origin = target + glm::normalize(normal) * (Real(1) + Real(30) * rng.next_real()) +
                                random_point() * Real(0.5);
            quad_rays.push_back({origin, glm::normalize(target - origin)});
        }
        const ShaderProbe probe(gl(), flattened(scene));
        for (const ProbeHit& h : probe.nearest_hits(quad_rays, kInfinity)) misses += h.hit ? 0 : 1;
        total += quad_rays.size();
        check_against_world(scene, quad_rays, 4);
    }
    CHECK(total > 3000);
    CHECK(misses == 0);
}

TEST_CASE("Shader triangles 1e-14 from the ray's origin are hit as chapter 02 hits them",
          "[gpu]" SHADER_EXERCISES "[stability][ex:ch02.slab_widening][ex:ch02.wide_bvh_traversal]") {
    // The scaled distance T, a product of three coordinates, is about 1e-42 here: a float subnormal, which
    // GLSL lets a GPU flush to zero. The shader then decides the hit in double, as chapter 02 does.
    const Real a = Real(-4.65335803e-15), v = Real(-1.87248898e-14);
    const Ray diagonal{Vec3(a), glm::normalize(Vec3(-1))};
    const double corner_distance = (double(a) - double(v)) / -double(diagonal.direction.x);
    // The fuzzer's two triangles, meeting at a corner on the ray (chapter 02's test): both hit there.
    for (const TriangleShape& corner :
         {TriangleShape{{Vec3{a, Real(-2.57647920e-15), a}, Vec3{a, Real(-1.86134321e-14), v}, Vec3(v)}},
          TriangleShape{{Vec3{0, v, Real(-1.86134321e-14)}, Vec3(v), Vec3{Real(-9.36244490e-15), v, v}}}}) {
        const ShaderProbe probe(gl(), flattened(scene_of({Shape{corner, 0, "corner"}})));
        const ProbeHit hit = probe.nearest_hits({diagonal}, kInfinity)[0];
        REQUIRE(hit.hit);
        CHECK(std::abs(double(hit.t) - corner_distance) < 1e-6 * corner_distance);
    }
    // At each scale, 100 triangles 50 sizes apart along x, each met by 4 rays from about its own size away.
    Pcg32 rng(9, 15);
    auto near = [&](double x, double size) {
        const Vec3d offset{rng.next_real(), rng.next_real(), rng.next_real()};
        return Vec3(Vec3d(x, 0, 0) + (2.0 * offset - 1.0) * size);
    };
    for (const double scale : {1e-13, 1e-14, 1e-15}) {
        std::vector<Shape> triangles;
        std::vector<Ray> rays;
        for (int i = 0; i < 100; ++i) {
            const double x = 50 * scale * i;
            const TriangleShape tri{{near(x, scale), near(x, scale), near(x, scale)}};
            triangles.push_back(Shape{tri, 0, "t" + std::to_string(i)});
            for (int k = 0; k < 4; ++k) {
                const Vec3d target =
                    (Vec3d(tri.vertices[0]) + Vec3d(tri.vertices[1]) + Vec3d(tri.vertices[2])) / 3.0;
                const Vec3 origin = near(x, 3 * scale);
                rays.push_back({origin, Vec3(glm::normalize(target - Vec3d(origin)))});
            }
        }
        INFO("scale " << scale);
        const ShaderProbe probe(gl(), flattened(scene_of(triangles)));
        std::size_t hits = 0;
        for (const ProbeHit& h : probe.nearest_hits(rays, kInfinity)) hits += h.hit ? 1 : 0;
        CHECK(hits > 350);
        check_against_world(scene_of(triangles), rays, 4);
    }
}

TEST_CASE("Shader spheres small and far, huge and near, are hit as chapter 02 hits them",
          "[gpu]" SHADER_EXERCISES "[stability][ex:ch02.sphere_stable]") {
    Pcg32 rng(23, 9);
    std::int64_t largest = 0;
    for (const Real radius : {Real(0.1), Real(0.01)}) {
        for (const Real distance : {Real(10), Real(400), Real(1e3), Real(1e4)}) {
            const Sphere sphere{{0.3f, -0.2f, 0.1f}, radius};
            std::vector<Ray> rays;
            for (int i = 0; i < 500; ++i) {
                const Vec3 axis = random_unit(rng);
                const Vec3 side = glm::normalize(glm::cross(axis, random_unit(rng)));
                const Vec3 target = sphere.center + side * (Real(0.95) * radius * rng.next_real());
                rays.push_back({sphere.center + axis * distance,
                                glm::normalize(target - (sphere.center + axis * distance))});
            }
            INFO("radius " << radius << ", distance " << distance);
            largest = std::max(
                largest, check_against_world(
                             scene_of({Shape{SphereShape{sphere.center, sphere.radius}, 0, "s"}}), rays, 4));
        }
    }
    // Origins 1e-3 outside a sphere of radius 1e4: the textbook quadratic's worst case.
    std::vector<Ray> near;
    for (int i = 0; i < 200; ++i) {
        const Vec3 axis = random_unit(rng);
        near.push_back({axis * (1e4f + 1e-3f), -axis});
    }
    largest = std::max(
        largest, check_against_world(scene_of({Shape{SphereShape{{0, 0, 0}, 1e4f}, 0, "huge"}}), near, 4));
    WARN("spheres: t of the shader and of chapter 02 at most " << largest << " ulps apart");
}

TEST_CASE("Shader rays parallel to triangles, and degenerate triangles, give no hit",
          "[gpu]" SHADER_EXERCISES "[stability]") {
    const Scene flat =
        scene_of({Shape{TriangleShape{{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}}, 0, "flat"}});
    const std::vector<Ray> parallel{{{-1, 0.2f, 0}, {1, 0, 0}}, {{-1, 0.2f, 0.5f}, {1, 0, 0}}};
    for (const ProbeHit& h : ShaderProbe(gl(), flattened(flat)).nearest_hits(parallel, kInfinity))
        CHECK_FALSE(h.hit);
    const Scene degenerate =
        scene_of({Shape{TriangleShape{{Vec3{0, 0, -1}, Vec3{0, 0, -1}, Vec3{1, 1, -1}}}, 0, "repeated"},
                  Shape{TriangleShape{{Vec3{0, 0, -1}, Vec3{1, 1, -1}, Vec3{2, 2, -1}}}, 0, "collinear"},
                  Shape{TriangleShape{{Vec3{0.5f, 0.5f, -1}, Vec3{0.5f, 0.5f, -1}, Vec3{0.5f, 0.5f, -1}}}, 0,
                        "point"}});
    const std::vector<Ray> down{{{0.5f, 0.5f, 0}, {0, 0, -1}}};
    for (const ProbeHit& h : ShaderProbe(gl(), flattened(degenerate)).nearest_hits(down, kInfinity))
        CHECK_FALSE(h.hit);
}

namespace {

struct Agreement {
    double gpu_cpu;    // relative MSE between GPU and CPU images of different seeds (mean of two pairs)
    double cpu_cpu;    // the same between CPU images of different seeds: σ²_CPU + σ²_CPU
    double same_seed;  // between the GPU's and the CPU's image of one seed: the same paths, rounding apart
    double mean_gpu, mean_cpu;  // of that one seed's images
};

// The shader draws chapter 06's stratified Pcg32 numbers, so the CPU renders with --sampler stratified; both
// end paths at the scene's max_depth, as the executables do.
Image cpu_image(const Scene& scene, RenderSettings settings, std::uint64_t seed) {
    settings.seed = seed;
    PathOptions options;
    options.sampler = PointSet::kStratified;
    options.termination.max_depth = scene.max_depth.value_or(options.termination.max_depth);
    return render_with(Renderer::kPaths, scene, needed(scene), settings, options).image;
}

// The scene at 48×48 pixels, 64 spp, with chapter 07's path renderer on the CPU (seeds 1, 2, 3) and with
// the shader of `kind` (seeds 1, 4, 5).
Agreement agreement(const Scene& scene, ShaderKind kind) {
    RenderSettings settings;
    settings.width = 48;
    settings.height = 48;
    settings.samples_per_pixel = 64;
    settings.threads = 2;
    settings.progress = ProgressStyle::kNone;
    const Image cpu1 = cpu_image(scene, settings, 1), cpu2 = cpu_image(scene, settings, 2),
                cpu3 = cpu_image(scene, settings, 3);
    const GpuRenderer renderer(gl(), scene, needed(scene), kind);
    auto gpu_image = [&](std::uint64_t seed) {
        settings.seed = seed;
        return renderer.render(settings).image;
    };
    const Image gpu1 = gpu_image(1), gpu4 = gpu_image(4), gpu5 = gpu_image(5);
    return {(compare(gpu4, cpu1).relative_mse + compare(gpu5, cpu2).relative_mse) / 2,
            (compare(cpu3, cpu1).relative_mse + compare(cpu3, cpu2).relative_mse) / 2,
            compare(gpu1, cpu1).relative_mse, gpu1.mean(), cpu1.mean()};
}

Agreement agreement(const std::string& file, ShaderKind kind) {
    return agreement(load_scene(scene_path(file.c_str())), kind);
}

void check_agreement(const std::string& file, ShaderKind kind, const Scene* scene = nullptr) {
    const Agreement a = scene ? agreement(*scene, kind) : agreement(file, kind);
    INFO(file << ", " << to_string(kind) << " shader: relative MSE GPU-CPU " << a.gpu_cpu << ", CPU-CPU "
              << a.cpu_cpu << ", same seed " << a.same_seed << "; means " << a.mean_gpu << " and "
              << a.mean_cpu);
    // Two independent images of one estimator differ by σ²_GPU + σ²_CPU on average, a bias adds its square;
    // the estimate of a relative MSE from 48×48 pixels with the glass's fireflies varies by tens of percent.
    // A noiseless scene (an index-matched furnace) must agree to rounding.
    if (a.cpu_cpu > 1e-12) {
        CHECK(a.gpu_cpu < 2 * a.cpu_cpu);
        CHECK(a.gpu_cpu > 0.5 * a.cpu_cpu);
    } else {
        CHECK(a.gpu_cpu < 1e-12);
    }
    // One seed: the same random numbers drive the same paths.
    CHECK(a.same_seed <= 1e-3 * std::max(a.cpu_cpu, 1e-12));
    CHECK(std::abs(a.mean_gpu - a.mean_cpu) < 0.01 * a.mean_cpu);
}

}  // namespace

TEST_CASE("The compute shader's glass Cornell box agrees with the CPU's within the noise",
          "[gpu]" SHADER_EXERCISES
          "[image][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]"
          "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    check_agreement("cornell.json", ShaderKind::kCompute);
}

TEST_CASE("The fragment shader's glass Cornell box agrees with the CPU's within the noise",
          "[gpu]" SHADER_EXERCISES
          "[image][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]"
          "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    check_agreement("cornell.json", ShaderKind::kFragment);
}

TEST_CASE(
    "The compute shader ends paths at the scene's max_depth as the CPU does, the ray drawn there included",
    "[gpu]" SHADER_EXERCISES
    "[image][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch03.robust_offset]"
    "[ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light]"
    "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]") {
    // Chapter 05's furnace at depth 2 (1 + ρ + ρ² = 2.44): the light of the second bounce is shared by MIS
    // between the next-event estimate and the ray drawn at the cap, which must be traced.
    Scene scene = load_scene(scene_path("ch05_furnace.json"));
    scene.max_depth = 2;
    check_agreement("ch05_furnace.json at depth 2", ShaderKind::kCompute, &scene);
}

// Chapter 07's other scenes: ch07_default.json is the glass Cornell box above; its furnaces are below.
TEST_CASE("The compute shader renders chapter 07's coloured glass as the CPU does",
          "[gpu]" SHADER_EXERCISES
          "[image][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]"
          "[ex:ch07.beer_lambert][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    check_agreement("ch07_coloured_glass.json", ShaderKind::kCompute);
}

TEST_CASE("The compute shader renders chapter 07's glossy surfaces and glass as the CPU does",
          "[gpu]" SHADER_EXERCISES
          "[image][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.glossy]"
          "[ex:ch04.lambert][ex:ch04.power_cosine][ex:ch04.power_cosine_pdf][ex:ch04.sample_quad_light]"
          "[ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch07.dielectric_sample]"
          "[ex:ch07.fresnel_exact][ex:ch07.refract]") {
    check_agreement("ch07_glossy_glass.json", ShaderKind::kCompute);
}

TEST_CASE("The compute shader's thin lens renders the glass Cornell box out of focus as the CPU does",
          "[gpu]" SHADER_EXERCISES
          "[image][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]"
          "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    // Chapter 01's lens, 20 units wide, focused on the sphere (about 610 from the eye): the walls blur.
    Scene scene = load_scene(scene_path("cornell.json"));
    scene.camera.aperture = 20;
    scene.camera.focus_distance = 610;
    check_agreement("cornell.json with a thin lens", ShaderKind::kCompute, &scene);
}

TEST_CASE(
    "The compute shader renders spot and distant lights as the CPU does",
    "[gpu]" SHADER_EXERCISES
    "[image][lights][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
    "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
    "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]"
    "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    // The glass Cornell box, its lamp dimmed, lit also by a spot on the floor (its band crossing the glass
    // sphere) and by a distant light slanting in through the open front.
    Scene scene = load_scene(scene_path("cornell.json"));
    for (Material& m : scene.materials) m.emission *= Real(0.25);
    scene.spot_lights.push_back(SpotLight{{278, 540, 278}, {278, 0, 278}, Color(2e5f), 35, 15});
    scene.distant_lights.push_back(DistantLight{glm::normalize(Vec3(0.3f, -0.5f, 1)), Color(3)});
    check_agreement("cornell.json with a spot and a distant light", ShaderKind::kCompute, &scene);
}

TEST_CASE("The shader's white furnaces of glass return the light of the sky",
          "[gpu]" SHADER_EXERCISES "[image]") {
    // A glass sphere under a uniform sky of radiance 1, in nothing else: every path returns 1 (chapter 07).
    for (const char* file : {"ch07_furnace_glass.json", "ch07_furnace_eta1.json"}) {
        const Scene scene = load_scene(scene_path(file));
        RenderSettings settings;
        settings.width = 32;
        settings.height = 32;
        settings.samples_per_pixel = 64;
        settings.seed = 7;
        settings.progress = ProgressStyle::kNone;
        const RenderResult r = GpuRenderer(gl(), scene, needed(scene), ShaderKind::kCompute).render(settings);
        INFO(file);
        CHECK(r.image.mean() == Approx(1).epsilon(1e-3));
    }
}
