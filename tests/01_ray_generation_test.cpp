// Tests of chapter 01: the pinhole camera, where samples fall in a pixel, and the exact edge coverage.
#include <catch2/catch.hpp>
#include <cmath>

#include "01_ray_generation/camera.hpp"
#include "01_ray_generation/edge_coverage.hpp"
#include "01_ray_generation/pixel_sampling.hpp"
#include "01_ray_generation/ray_generation_render.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"

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
    // Stratum i of n × n = 4 × 4 is [i % 4, i % 4 + 1) × [i / 4, i / 4 + 1) / 4, and u places the sample in it.
    for (const Vec2 u : {Vec2(0.1f, 0.7f), Vec2(0.6f, 0.2f)}) {
        const Vec2 p = pixel_sample_point(PixelSampler::kStratified, 3, 4, 6, 16, u);
        CHECK(p.x == Approx(3 + (2 + u.x) / 4));
        CHECK(p.y == Approx(4 + (1 + u.y) / 4));
    }
    // 5 samples: 2 × 2 strata, and the fifth uniform over the whole pixel.
    const Vec2 fifth = pixel_sample_point(PixelSampler::kStratified, 3, 4, 4, 5, Vec2(0.3f, 0.8f));
    CHECK(fifth.x == Approx(3.3));
    CHECK(fifth.y == Approx(4.8));
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
