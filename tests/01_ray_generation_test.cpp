// Tests of chapter 01: the pinhole camera, where samples fall in a pixel, and the exact edge coverage.
#include <catch2/catch.hpp>
#include <cmath>

#include "01_ray_generation/camera.hpp"
#include "01_ray_generation/camera_render.hpp"
#include "01_ray_generation/concentric_disk.hpp"
#include "01_ray_generation/edge_coverage.hpp"
#include "01_ray_generation/pixel_sampling.hpp"
#include "01_ray_generation/ray_generation_render.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"
#include "support/chi_square.hpp"

using namespace rt;

namespace {

CameraDesc looking_down_z(Real vfov = 60) {
    return CameraDesc{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, vfov};
}

double angle_between(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0));
}

}  // namespace

TEST_CASE("The centre of the film looks straight ahead", "[ch01][ex:ch01.camera_ray]") {
    const PinholeCamera camera = make_pinhole_camera(looking_down_z(), 640, 360);
    const Ray ray = camera_ray(camera, 320, 180);
    CHECK(ray.origin == Vec3(0));
    CHECK(ray.direction.x == Approx(0).margin(1e-7));
    CHECK(ray.direction.y == Approx(0).margin(1e-7));
    CHECK(ray.direction.z == Approx(-1));
}

TEST_CASE("The top and bottom edge rays make half the vertical field of view with the view",
          "[ch01][ex:ch01.camera_ray]") {
    for (Real vfov : {10.0f, 40.0f, 90.0f, 150.0f}) {
        const PinholeCamera camera = make_pinhole_camera(looking_down_z(vfov), 200, 100);
        const Vec3 ahead = camera.forward;
        CHECK(angle_between(camera_ray(camera, 100, 0).direction, ahead) ==
              Approx(radians(vfov / 2)).epsilon(1e-5));
        CHECK(angle_between(camera_ray(camera, 100, 100).direction, ahead) ==
              Approx(radians(vfov / 2)).epsilon(1e-5));
        CHECK(camera_ray(camera, 100, 0).direction.y > 0);  // the top row looks up
    }
}

TEST_CASE("The horizontal field of view follows the aspect ratio", "[ch01][ex:ch01.camera_ray]") {
    const PinholeCamera camera = make_pinhole_camera(looking_down_z(60), 400, 100);
    const double half_horizontal = angle_between(camera_ray(camera, 400, 50).direction, camera.forward);
    CHECK(std::tan(half_horizontal) == Approx(4 * std::tan(radians(30))).epsilon(1e-5));
    CHECK(camera_ray(camera, 400, 50).direction.x > 0);  // the right column looks right
}

TEST_CASE("Every camera ray has unit length", "[ch01][ex:ch01.camera_ray]") {
    const PinholeCamera camera =
        make_pinhole_camera(CameraDesc{{1, 2, 3}, {-4, 5, 6}, {0, 1, 0}, 75}, 97, 61);
    for (int y = 0; y <= 61; ++y)
        for (int x = 0; x <= 97; ++x)
            REQUIRE(glm::length(camera_ray(camera, Real(x), Real(y)).direction) == Approx(1).epsilon(1e-6));
}

TEST_CASE("The camera basis stays orthonormal when up is nearly parallel to the view", "[ch01][stability]") {
    for (double tilt : {1e-3, 1e-5, 1e-7}) {
        INFO("up tilted by " << tilt);
        const CameraDesc desc{{0, 0, 0}, {0, 1, 0}, {Real(tilt), 1, 0}, 45};
        const PinholeCamera c = make_pinhole_camera(desc, 64, 64);
        CHECK(glm::length(c.forward) == Approx(1));
        CHECK(glm::length(c.right) == Approx(1));
        CHECK(glm::length(c.up) == Approx(1));
        CHECK(std::abs(glm::dot(c.forward, c.right)) < 1e-6);
        CHECK(std::abs(glm::dot(c.forward, c.up)) < 1e-6);
        CHECK(std::abs(glm::dot(c.right, c.up)) < 1e-6);
    }
}

TEST_CASE("A camera whose up is exactly parallel to the view is refused with a clear error",
          "[ch01][stability]") {
    CHECK_THROWS_WITH(make_pinhole_camera(CameraDesc{{0, 0, 0}, {0, 3, 0}, {0, 1, 0}, 45}, 8, 8),
                      Catch::Contains("camera.up") && Catch::Contains("parallel"));
    CHECK_THROWS_WITH(make_pinhole_camera(CameraDesc{{0, 0, 0}, {0, -3, 0}, {0, 1, 0}, 45}, 8, 8),
                      Catch::Contains("parallel"));
    CHECK_THROWS_AS(make_pinhole_camera(CameraDesc{{1, 1, 1}, {1, 1, 1}, {0, 1, 0}, 45}, 8, 8), InputError);
    CHECK_THROWS_AS(make_pinhole_camera(looking_down_z(), 0, 8), InputError);
}

TEST_CASE("Jittered samples stay inside their pixel for random numbers 0 and just below 1",
          "[ch01][stability][ex:ch01.pixel_sample]") {
    // The naive film point x + u leaves the pixel: in float, 3 + (1 − 2⁻²⁴) rounds to 4.
    CHECK(Real(3) + kOneMinusEpsilon == Real(4));
    const Vec2 lowest(0, 0), highest(kOneMinusEpsilon, kOneMinusEpsilon);
    for (PixelSampler sampler : {PixelSampler::kCenter, PixelSampler::kUniform, PixelSampler::kStratified}) {
        for (int count : {1, 2, 4, 16, 17, 256}) {
            for (int index = 0; index < count; ++index) {
                for (const Vec2& u : {lowest, highest}) {
                    // Far from the origin a float has fewer bits below the point: the hardest pixel.
                    for (int x : {0, 7, 4095}) {
                        const Vec2 p = pixel_sample_point(sampler, x, 3, index, count, u);
                        INFO(to_string(sampler) << " count " << count << " index " << index << " x " << x);
                        REQUIRE(p.x >= Real(x));
                        REQUIRE(p.x < Real(x + 1));
                        REQUIRE(p.y >= 3);
                        REQUIRE(p.y < 4);
                    }
                }
            }
        }
    }
}

TEST_CASE("Stratified samples put one sample in each stratum", "[ch01][ex:ch01.pixel_sample]") {
    const int n = 4;
    std::vector<int> hits(n * n, 0);
    for (int i = 0; i < n * n; ++i) {
        const Vec2 p = pixel_sample_point(PixelSampler::kStratified, 0, 0, i, n * n, Vec2(0.5f));
        ++hits[std::size_t(int(p.y * n) * n + int(p.x * n))];
    }
    for (int h : hits) CHECK(h == 1);
}

TEST_CASE("A pixel sample: the centre, u within its stratum, and samples beyond the strata anywhere in it",
          "[ch01][ex:ch01.pixel_sample]") {
    // The centre sampler takes the pixel's centre, whatever u is.
    CHECK(pixel_sample_point(PixelSampler::kCenter, 3, 4, 0, 1, Vec2(0.9f, 0.1f)) == Vec2(3.5f, 4.5f));
    // Any correct jitter passes (u or 1 − u, any order of the strata): sample 6 of 4 × 4 stays in one stratum
    // whatever u is, and moves by exactly a quarter of u's step along each axis, so its density is uniform
    // over that stratum (the Jacobian of u to the film point is 1/16: 16 times the pixel's density).
    auto point = [](int index, int count, Vec2 u) {
        return pixel_sample_point(PixelSampler::kStratified, 3, 4, index, count, u);
    };
    const Vec2 middle = point(6, 16, Vec2(0.5f));
    const Vec2 stratum = glm::floor((middle - Vec2(3, 4)) * Real(4));
    for (const Vec2 u : {Vec2(0.1f, 0.7f), Vec2(0.6f, 0.2f), Vec2(0.01f, 0.99f)}) {
        const Vec2 p = point(6, 16, u);
        INFO("u = (" << u.x << ", " << u.y << "): the sample leaves its stratum, or is not uniform over it (a "
             "Jacobian other than 1/16 from u to the film point)");
        CHECK(glm::floor((p - Vec2(3, 4)) * Real(4)) == stratum);
        CHECK(std::abs(p.x - middle.x) == Approx(std::abs(u.x - 0.5) / 4).margin(1e-6));
        CHECK(std::abs(p.y - middle.y) == Approx(std::abs(u.y - 0.5) / 4).margin(1e-6));
    }
    // 5 samples: 2 × 2 strata, and the fifth uniform over the whole pixel (a step of u moves it as far).
    const Vec2 fifth = point(4, 5, Vec2(0.3f, 0.8f)), fifth_middle = point(4, 5, Vec2(0.5f));
    CHECK(glm::floor(fifth) == Vec2(3, 4));
    CHECK(std::abs(fifth.x - fifth_middle.x) == Approx(0.2).margin(1e-6));
    CHECK(std::abs(fifth.y - fifth_middle.y) == Approx(0.3).margin(1e-6));
}

TEST_CASE("Exact edge coverage: whole pixels, half pixels, and the film's total area", "[ch01]") {
    const PinholeCamera camera = make_pinhole_camera(looking_down_z(), 64, 48);
    const FilmEdge vertical = make_film_edge(camera, 0);  // normal = right: the right half of the film
    CHECK(exact_coverage(vertical, 40, 10) == Approx(1));
    CHECK(exact_coverage(vertical, 10, 10) == Approx(0).margin(1e-12));
    const FilmEdge tilted = make_film_edge(camera, 20);
    // The edge passes through the film centre, so by symmetry it covers exactly half the film.
    double total = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) total += exact_coverage(tilted, x, y);
    CHECK(total == Approx(64 * 48 / 2.0).epsilon(1e-9));
}

TEST_CASE("Coverage from many stratified samples converges to the exact coverage",
          "[ch01][statistical][ex:ch01.camera_ray][ex:ch01.pixel_sample]") {
    const PinholeCamera camera = make_pinhole_camera(looking_down_z(), 48, 32);
    const FilmEdge edge = make_film_edge(camera, 20);
    RenderSettings settings{48, 32, 256, 3, 1, ProgressStyle::kNone};
    const double stratified =
        edge_rmse(render_coverage(camera, edge, PixelSampler::kStratified, settings).image, edge);
    const double uniform =
        edge_rmse(render_coverage(camera, edge, PixelSampler::kUniform, settings).image, edge);
    settings.samples_per_pixel = 1;
    const double centre =
        edge_rmse(render_coverage(camera, edge, PixelSampler::kCenter, settings).image, edge);
    CHECK(stratified < 0.02);
    CHECK(stratified < uniform);  // stratification beats independent jitter at the same count
    CHECK(uniform < centre);      // and any anti-aliasing beats one sample at the centre
}

TEST_CASE("Chapter 01's default scene renders: finite, plausible and deterministic",
          "[ch01][ex:ch01.camera_ray][ex:ch01.pixel_sample]") {
    const Scene scene = load_scene(scene_path("ch01_default.json"));
    RenderSettings settings{64, 36, 4, 1, 2, ProgressStyle::kNone};
    const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
    const FilmEdge edge = make_film_edge(camera, 20);
    const RenderResult a = render_directions(camera, edge, PixelSampler::kStratified, settings);
    const RenderResult b = render_directions(camera, edge, PixelSampler::kStratified, settings);
    CHECK(a.image.all_finite());
    CHECK(a.image.mean() > 0.4);
    CHECK(a.image.mean() < 1.0);
    CHECK(a.rays[RayKind::kCamera] == 64u * 36u * 4u);
    CHECK(a.rays.total() == a.rays[RayKind::kCamera]);
    for (std::size_t i = 0; i < a.image.pixel_count(); ++i)
        REQUIRE(a.image.pixels()[i] == b.image.pixels()[i]);
}

// ---------------------------------------------------------------------------------------------------------
// The thin lens (camera.hpp) and the concentric map (concentric_disk.hpp)

namespace {

CameraDesc thin_lens(Real aperture, std::optional<Real> focus = std::nullopt) {
    CameraDesc desc{{1, 2, 3}, {1, 2, -5}, {0, 1, 0}, 50};
    desc.aperture = aperture;
    desc.focus_distance = focus;
    return desc;
}

// Where `ray` meets the plane at `depth` along the camera's view direction w.
Vec3 at_depth(const PinholeCamera& camera, const Ray& ray, Real depth) {
    const Real t =
        (depth - glm::dot(ray.origin - camera.eye, camera.forward)) / glm::dot(ray.direction, camera.forward);
    return ray.origin + t * ray.direction;
}

}  // namespace

TEST_CASE("The concentric map is uniform on the disk: chi-square over cells of equal area",
          "[ch01][statistical]") {
    // Cells in (r², φ): 20 rings of equal area times 40 sectors, each 1/800 of the disk.
    constexpr int kRings = 20, kSectors = 40, kSamples = 400000;
    std::vector<double> observed(kRings * kSectors, 0), expected(kRings * kSectors, double(kSamples) / 800);
    Pcg32 rng(101, 3);
    int outside = 0;
    for (int i = 0; i < kSamples; ++i) {
        const Vec2 p = sample_disk_concentric(rng.next_vec2());
        const double r2 = double(p.x) * p.x + double(p.y) * p.y;
        if (!(r2 <= 1 + 1e-6)) {
            ++outside;
            continue;
        }
        double phi = std::atan2(double(p.y), double(p.x));
        if (phi < 0) phi += 2 * std::numbers::pi;
        const int ring = std::min(kRings - 1, int(r2 * kRings));
        const int sector = std::min(kSectors - 1, int(phi / (2 * std::numbers::pi) * kSectors));
        observed[std::size_t(ring * kSectors + sector)] += 1;
    }
    const test::ChiSquare r = test::chi_square(observed, expected);
    INFO("chi-square " << r.statistic << ", " << r.dof << " dof, p = " << r.p_value);
    CHECK(outside == 0);
    CHECK(r.p_value > 0.01);
}

TEST_CASE("The concentric map sends the square's centre to the disk's, and its border onto the circle",
          "[ch01]") {
    CHECK(sample_disk_concentric({0.5f, 0.5f}) == Vec2(0));
    for (Real t : {0.0f, 0.1f, 0.37f, 0.5f, 0.8f, 0.999f}) {
        for (const Vec2 u : {Vec2(0, t), Vec2(t, 0), Vec2(1, t), Vec2(t, 1)}) {
            CHECK(glm::length(sample_disk_concentric(u)) == Approx(1).margin(1e-6));
        }
    }
}

TEST_CASE("A thin lens: every ray of a film point passes through its pinhole ray's point in focus",
          "[ch01][ex:ch01.camera_ray]") {
    const PinholeCamera camera = make_pinhole_camera(thin_lens(0.3f, 4.0f), 64, 48);
    Pcg32 rng(7, 1);
    for (int i = 0; i < 200; ++i) {
        const Real px = 64 * rng.next_real(), py = 48 * rng.next_real();
        const Vec3 focus = at_depth(camera, camera_ray(camera, px, py), 4);
        const Ray ray = thin_lens_ray(camera, px, py, rng.next_vec2());
        CHECK(glm::length(ray.direction) == Approx(1).margin(1e-6));
        // The ray starts on the lens: in the plane of u and v through the eye, within the aperture.
        const Vec3 offset = ray.origin - camera.eye;
        CHECK(std::abs(glm::dot(offset, camera.forward)) < 1e-5);
        CHECK(glm::length(offset) <= 0.3f * (1 + 1e-5f));
        CHECK(glm::length(at_depth(camera, ray, 4) - focus) < 2e-5);
    }
}

TEST_CASE("A thin lens spreads a point off the plane in focus over aperture times |1 - depth / focus|",
          "[ch01][ex:ch01.camera_ray]") {
    // The rays from the lens's rim (the square's border) meet the plane at `depth` on a circle of that radius
    // around the pinhole ray's point: the circle of confusion, measured in the scene.
    const PinholeCamera camera = make_pinhole_camera(thin_lens(0.25f, 5.0f), 32, 32);
    for (Real depth : {2.0f, 5.0f, 12.0f}) {
        const Vec3 centre = at_depth(camera, camera_ray(camera, 10.5f, 20.5f), depth);
        for (Real t : {0.0f, 0.3f, 0.75f}) {
            const Ray rim = thin_lens_ray(camera, 10.5f, 20.5f, {1, t});
            CHECK(glm::length(at_depth(camera, rim, depth) - centre) ==
                  Approx(0.25 * std::abs(1 - depth / 5.0)).margin(1e-5));
        }
    }
}

TEST_CASE(
    "The focus distance defaults to |at - from|, and a negative aperture or a focus distance of 0 is refused",
    "[ch01]") {
    CHECK(make_pinhole_camera(thin_lens(0.1f), 8, 8).focus_distance == 8);
    CHECK(make_pinhole_camera(thin_lens(0.1f, 2.5f), 8, 8).focus_distance == 2.5f);
    CHECK(make_pinhole_camera(looking_down_z(), 8, 8).lens_radius == 0);
    CHECK_THROWS_AS(make_pinhole_camera(thin_lens(-0.1f), 8, 8), InputError);
    CHECK_THROWS_AS(make_pinhole_camera(thin_lens(0.1f, 0.0f), 8, 8), InputError);
}

TEST_CASE("Aperture 0 is the pinhole bit for bit and draws no random number more, where a lens draws two",
          "[ch01][ex:ch01.camera_ray][ex:ch01.pixel_sample]") {
    // Each sample shows its ray's direction and the next number of its generator: what the camera left.
    RenderSettings settings{16, 12, 4, 1, 2, ProgressStyle::kNone};
    const auto render_of = [&](const CameraDesc& desc) {
        const PinholeCamera camera = make_pinhole_camera(desc, settings.width, settings.height);
        return render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
            const Ray ray = camera_ray_of(camera, PixelSampler::kStratified, s, 4, rng, rays);
            return ray.direction + ray.origin + Color(rng.next_real());
        });
    };
    CameraDesc pinhole = thin_lens(0);
    pinhole.focus_distance = std::nullopt;
    const RenderResult a = render_of(pinhole);
    const RenderResult b = render_of(thin_lens(0, 3.0f));  // a focus distance without aperture: no lens
    const RenderResult c = render_of(thin_lens(0.2f));
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.image.pixel_count(); ++i) {
        REQUIRE(a.image.pixels()[i] == b.image.pixels()[i]);
        differ += a.image.pixels()[i] != c.image.pixels()[i];
    }
    CHECK(differ == a.image.pixel_count());
    CHECK(a.rays[RayKind::kCamera] == c.rays[RayKind::kCamera]);
}

TEST_CASE("The scene's camera takes aperture and focus_distance", "[ch01]") {
    const Scene scene = parse_scene(R"({
      "camera": {"from": [0, 0, 5], "at": [0, 0, 0], "aperture": 0.05, "focus_distance": 3},
      "materials": {"m": {"type": "diffuse"}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]
    })",
                                    "lens.json");
    CHECK(scene.camera.aperture == 0.05f);
    CHECK(scene.camera.focus_distance == 3.0f);
    const Scene pinhole = load_scene(scene_path("ch01_default.json"));
    CHECK(pinhole.camera.aperture == 0);
    CHECK_FALSE(pinhole.camera.focus_distance);
}
