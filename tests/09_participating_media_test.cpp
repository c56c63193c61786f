// Chapter 09: participating media. The Henyey–Greenstein phase function (it integrates to 1, its mean cosine
// is g, its sampling fits its density by chi-square, no NaN at g = ±0.999), free flight (exponential
// distances, its weights, spectral MIS against the naive per-channel density), transmittance exp(−σ_t d)
// through fog and a slab (camera rays and shadow rays), white furnaces (a sphere of albedo 1 under a sky of
// radiance 1 reads 1 at every pixel: index-matched and ior 1.5, g = 0 and 0.7, chromatic σ_s), single
// scattering in a slab against its quadrature, a semi-infinite medium against Chandrasekhar's H function,
// energy, no NaN at the extremes, the scene format's media, the notes of chapters that cannot simulate them,
// the default scene; equiangular distance sampling (its chi-square fit, its density's integral, the light on
// the ray's line, an exact single-scattering reference for each --distance-sampling, the thin fog alike).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "07_bsdf_refraction/refraction_materials.hpp"
#include "08_forward_tracing/combined_render.hpp"
#include "09_participating_media/equiangular.hpp"
#include "09_participating_media/henyey_greenstein.hpp"
#include "09_participating_media/homogeneous_medium.hpp"
#include "09_participating_media/media_materials.hpp"
#include "09_participating_media/media_notes.hpp"
#include "09_participating_media/media_scenes.hpp"
#include "09_participating_media/tracer_choice.hpp"
#include "09_participating_media/volume_path_tracer.hpp"
#include "rt/io/effects.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"
#include "support/chi_square.hpp"

using namespace rt;

namespace {

constexpr double kPiD = std::numbers::pi;

// 2π ∫ p(cos θ) k(cos θ) d cos θ by the trapezoidal rule on nodes dense where p peaks (cos θ = 1 for g ≥ 0,
// −1 for g < 0): x = 1 ∓ cos θ from 10⁻¹⁴ to 2 evenly in ln x (the peak is (1 − |g|)² wide), each node
// rounded to the float the function takes, so the rule integrates what it evaluates.
template <class K>
double hg_moment(double g, K k) {
    std::vector<double> nodes{g >= 0 ? 1.0 : -1.0};
    const int n = 200000;
    const double a = std::log(1e-14), b = std::log(2.0);
    for (int i = 0; i <= n; ++i) {
        const double x = std::exp(a + (b - a) * i / n);
        const double c = double(Real(g >= 0 ? 1 - x : x - 1));
        if (c != nodes.back()) nodes.push_back(c);
    }
    double sum = 0;
    const auto f = [&](double c) { return double(henyey_greenstein(Real(c), Real(g))) * k(c); };
    for (std::size_t i = 1; i < nodes.size(); ++i)
        sum += std::abs(nodes[i] - nodes[i - 1]) * (f(nodes[i]) + f(nodes[i - 1])) / 2;
    return 2 * kPiD * sum;
}

// The radiance a VolumePathTracer returns along `ray`: the mean and standard error of `paths` paths, per
// channel (the green channel unless asked).
struct Estimate {
    double means[3] = {0, 0, 0}, errors[3] = {0, 0, 0};
    double mean = 0, error = 0;  // of the green channel
};
Estimate estimate(const VolumePathTracer& tracer, const Ray& ray, int paths, std::uint64_t seed) {
    double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
    RayCounts rays;
    for (int i = 0; i < paths; ++i) {
        Pcg32 rng = Pcg32::for_sample(seed, std::uint64_t(i), 91);
        const Color L = tracer.radiance(ray, rng, rays);
        for (int c = 0; c < 3; ++c) {
            sum[c] += double(L[c]);
            sum2[c] += double(L[c]) * double(L[c]);
        }
    }
    Estimate e;
    for (int c = 0; c < 3; ++c) {
        e.means[c] = sum[c] / paths;
        e.errors[c] = std::sqrt(std::max(0.0, sum2[c] / paths - e.means[c] * e.means[c]) / (paths - 1));
    }
    e.mean = e.means[1];
    e.error = e.errors[1];
    return e;
}

// A scene prepared as a run of chapter 09 prepares it: simulating what run_chapter() computes from the scene
// (needed ∩ supported), not every effect, so an exact answer checks the path a user's scene file takes.
struct Prepared {
    explicit Prepared(const Scene& s, PathOptions options = {}, MediumWalk walk = {})
        : scene(s),
          simulated(simulated_effects(scene, kMediaChapterEffects)),
          render(scene, simulated, media_materials()),
          tracer(render.world, render.materials, render.lights, simulating(options, simulated), walk) {}
    static PathOptions simulating(PathOptions options, const EffectSet& simulated) {
        options.simulated = simulated;
        return options;
    }
    Scene scene;
    EffectSet simulated;
    RenderScene render;
    VolumePathTracer tracer;
};

// Every pixel of an 6×6 view of the furnace sphere (the corners see the sky): the largest deviation from 1
// in standard errors, the largest standard error, and the mean over the pixels.
struct FurnaceCheck {
    double worst_sigmas = 0, largest_error = 0, mean = 0;
};
// Each channel's check, from one render of the 36 pixels.
std::vector<FurnaceCheck> furnace_channels(const MediumDesc& medium, Real ior, int paths) {
    const Prepared p(medium_sphere_scene(medium, ior));
    const PinholeCamera camera = make_pinhole_camera(p.scene.camera, 6, 6);
    std::vector<FurnaceCheck> f(3);
    for (int y = 0; y < 6; ++y) {
        for (int x = 0; x < 6; ++x) {
            const Ray ray = camera_ray(camera, Real(x) + 0.5f, Real(y) + 0.5f);
            const Estimate e = estimate(p.tracer, ray, paths, std::uint64_t(y * 6 + x));
            for (std::size_t c = 0; c < 3; ++c) {
                const double deviation = std::abs(e.means[c] - 1) / std::max(e.errors[c], 1e-7);
                f[c].worst_sigmas = std::max(f[c].worst_sigmas, deviation);
                f[c].largest_error = std::max(f[c].largest_error, e.errors[c]);
                f[c].mean += e.means[c] / 36;
            }
        }
    }
    return f;
}
FurnaceCheck furnace(const MediumDesc& medium, Real ior, int paths) {
    return furnace_channels(medium, ior, paths)[1];
}

// Gauss–Legendre nodes and weights on [0, 1] (Newton's method on P_n from the Chebyshev guesses).
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
    x.assign(std::size_t(n), 0);
    w.assign(std::size_t(n), 0);
    for (int i = 0; i < n; ++i) {
        double z = std::cos(kPiD * (i + 0.75) / (n + 0.5)), derivative = 1;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1, p1 = z;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = n * (z * p1 - p0) / (z * z - 1);
            const double step = p1 / derivative;
            z -= step;
            if (std::abs(step) < 1e-15) break;
        }
        x[std::size_t(i)] = (1 - z) / 2;
        w[std::size_t(i)] = 1 / ((1 - z * z) * derivative * derivative);  // 2 / (...) on [−1, 1], halved
    }
}

// Chandrasekhar's H function for isotropic scattering of albedo ω, by fixed-point iteration of
// H(μ) = 1 / (1 − (ω/2) μ ∫₀¹ H(μ') / (μ + μ') dμ') on a Gauss–Legendre rule; `moment` is ∫₀¹ H dμ.
struct HFunction {
    std::vector<double> mu, weight, h;
    double omega = 0;
    double operator()(double m) const {
        double integral = 0;
        for (std::size_t j = 0; j < mu.size(); ++j) integral += weight[j] * h[j] / (m + mu[j]);
        return 1 / (1 - omega / 2 * m * integral);
    }
    double moment() const {
        double sum = 0;
        for (std::size_t j = 0; j < mu.size(); ++j) sum += weight[j] * h[j];
        return sum;
    }
};
HFunction chandrasekhar_h(double omega) {
    HFunction H;
    H.omega = omega;
    gauss_legendre(96, H.mu, H.weight);
    H.h.assign(H.mu.size(), 1);
    for (int iteration = 0; iteration < 5000; ++iteration) {
        std::vector<double> next(H.mu.size());
        double change = 0;
        for (std::size_t i = 0; i < H.mu.size(); ++i) {
            next[i] = H(H.mu[i]);
            change = std::max(change, std::abs(next[i] - H.h[i]));
        }
        H.h = next;
        if (change < 1e-14) break;
    }
    return H;
}

Scene scene_from(const std::string& json) {
    return parse_scene(json, "test.json");
}

// A square render of `size` pixels a side, quiet, on two threads.
RenderSettings small_render(int size, int spp, std::uint64_t seed) {
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.samples_per_pixel = spp;
    settings.seed = seed;
    settings.threads = 2;
    settings.progress = ProgressStyle::kNone;
    return settings;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Henyey–Greenstein

// Up to |g| = 0.99: at 0.999 the peak is 5·10⁻⁷ wide in cos θ, 8 floats, too few for any rule to integrate
// the function of a float argument to 10⁻⁵ (its peak value is checked below instead).
TEST_CASE("Henyey-Greenstein integrates to 1 and its mean cosine is g, for g from -0.99 to 0.99", "") {
    for (double g : {-0.99, -0.7, -0.3, 0.0, 0.3, 0.7, 0.9, 0.99}) {
        INFO("g = " << g);
        CHECK(hg_moment(g, [](double) { return 1.0; }) == Approx(1).margin(2e-5));
        CHECK(hg_moment(g, [](double c) { return c; }) == Approx(g).margin(2e-5));
    }
}

TEST_CASE("Henyey-Greenstein sampling: the mean sampled cosine is g, and p / pdf is 1",
          "[statistical][ex:ch09.hg_sample]") {
    for (double g : {-0.8, -0.2, 0.0, 0.5, 0.95}) {
        const HenyeyGreenstein phase{Real(g)};
        Pcg32 rng(11, 3);
        const Vec3 wo = glm::normalize(Vec3(0.3f, -0.5f, 0.8f));
        const int n = 200000;
        double sum = 0, sum2 = 0;
        for (int i = 0; i < n; ++i) {
            const PhaseSample s = phase.sample(wo, rng.next_vec2());
            const double c = -double(glm::dot(wo, s.wi));
            sum += c;
            sum2 += c * c;
            REQUIRE(s.p == s.pdf);
        }
        const double mean = sum / n, error = std::sqrt((sum2 / n - mean * mean) / n);
        INFO("g = " << g << ", mean cosine " << mean << " +- " << error
                      << ": the samples' mean cosine is not g, a wrong inversion?");
        CHECK(std::abs(mean - g) < 5 * error);
    }
}

TEST_CASE("Henyey-Greenstein sample() fits eval() by chi-square over the sphere, g = -0.7, 0, 0.3, 0.9",
          "[statistical][ex:ch09.hg_sample]") {
    using namespace rt::test;
    const double level = sidak_level(4);
    // −wo along +x: the peak lies on the equator of the (z, φ) grid, where its cells are smallest.
    const Vec3 wo(-1, 0, 0);
    std::uint64_t seed = 900;
    for (double g : {-0.7, 0.0, 0.3, 0.9}) {
        INFO("g = " << g);
        const HenyeyGreenstein phase{Real(g)};
        const ChiSquare r = test_directions(
            [&](Vec2 u) {
                const PhaseSample s = phase.sample(wo, u);
                return Drawn{s.wi, double(s.pdf)};
            },
            [&](const Vec3& w) { return double(phase.eval(wo, w)); }, seed++);
        require_fit(r, level);
    }
}

TEST_CASE("Henyey-Greenstein at g = +-0.999: no NaN, unit directions, finite positive densities",
          "[stability][ex:ch09.hg_sample]") {
    for (double g : {-0.999, 0.999}) {
        const HenyeyGreenstein phase{Real(g)};
        const Vec3 wo = glm::normalize(Vec3(0.1f, 0.2f, -1));
        for (Real u0 : {Real(0), Real(1e-7), Real(0.5), kOneMinusEpsilon}) {
            for (Real u1 : {Real(0), Real(0.25), kOneMinusEpsilon}) {
                const PhaseSample s = phase.sample(wo, {u0, u1});
                INFO("g = " << g << ", u = " << u0 << ", " << u1);
                CHECK(is_finite(s.wi));
                CHECK(std::abs(glm::length(s.wi) - 1) < 1e-5f);
                CHECK(std::isfinite(s.p));
                CHECK(s.p > 0);
                CHECK(std::isfinite(phase.eval(wo, s.wi)));
            }
        }
        // The peak: (1 − g²) / (4π (1 − |g|)³) exactly, not lost to cancellation.
        const double peak = (1 - g * g) / (4 * kPiD * std::pow(1 - std::abs(g), 3));
        CHECK(henyey_greenstein(g > 0 ? 1 : -1, Real(g)) == Approx(peak).epsilon(1e-4));
    }
}

// ---------------------------------------------------------------------------------------------------------
// Free flight and transmittance

TEST_CASE(
    "Transmittance is exp(-sigma_t d) with sigma_t = sigma_a + sigma_s, and 1 at any distance where "
    "sigma_t is 0",
    "[ex:ch07.beer_lambert][ex:ch09.transmittance]") {
    const HomogeneousMedium m({Color(0.1f, 0, 0.5f), Color(0.2f, 0, 1.5f), 0.3f});
    for (Real d : {Real(0), Real(0.5), Real(3), Real(40)}) {
        const Color T = m.transmittance(d);
        CHECK(T.r == Approx(std::exp(-0.3 * d)).epsilon(1e-6));
        CHECK(T.g == 1);
        CHECK(T.b == Approx(std::exp(-2.0 * d)).epsilon(1e-6));
    }
    CHECK(m.transmittance(kInfinity) == Color(0, 1, 0));
}

TEST_CASE(
    "Free flight: distances are exponential with mean 1 / sigma_t, scattering weighs albedo, passing "
    "weighs 1",
    "[statistical][ex:ch07.beer_lambert][ex:ch09.free_flight]") {
    const Color sigma_t(2), sigma_s(1.5f);
    Pcg32 rng(5, 1);
    const int n = 100000;
    double sum = 0, sum2 = 0;
    int passed = 0;
    for (int i = 0; i < n; ++i) {
        const int channel = pick_channel(rng.next_real());
        const FreeFlight f = sample_free_flight(sigma_t, sigma_s, 1, channel, rng.next_real());
        REQUIRE(f.pdf_ratio == Color(1));  // the same density in every channel
        if (f.scattered) {
            REQUIRE(f.t < 1);
            REQUIRE(f.weight.g == Approx(0.75).epsilon(1e-6));  // ω = σ_s / σ_t
        } else {
            ++passed;
            REQUIRE(f.t == 1);
            REQUIRE(f.weight.g == Approx(1).epsilon(1e-6));
        }
        const FreeFlight unbounded =
            sample_free_flight(sigma_t, sigma_s, kInfinity, channel, rng.next_real());
        REQUIRE(unbounded.scattered);
        sum += double(unbounded.t);
        sum2 += double(unbounded.t) * double(unbounded.t);
    }
    const double mean = sum / n, error = std::sqrt((sum2 / n - mean * mean) / n);
    CHECK(std::abs(mean - 0.5) < 5 * error);
    // P(t >= 1) = e^−2.
    const double p = std::exp(-2.0), p_error = std::sqrt(p * (1 - p) / n);
    CHECK(std::abs(double(passed) / n - p) < 5 * p_error);
}

TEST_CASE(
    "Chromatic free flight: spectral MIS keeps every weight at most 3 and estimates the scattering "
    "probability, and the naive per-channel density gives unbounded weights",
    "[statistical][ex:ch07.beer_lambert][ex:ch09.free_flight]") {
    const Color sigma_t(0.25f, 1, 4);
    for (bool mis : {true, false}) {
        Pcg32 rng(6, 2);
        const int n = 200000;
        double largest = 0;
        std::vector<double> sums(3, 0), sums2(3, 0);
        for (int i = 0; i < n; ++i) {
            const int channel = pick_channel(rng.next_real());
            const FreeFlight f = sample_free_flight(sigma_t, sigma_t, 4, channel, rng.next_real());
            if (!f.scattered) continue;
            // Spectral MIS: the weight over the mean density ratio; naive: the weight alone.
            const Color w = mis ? f.weight / ((f.pdf_ratio.r + f.pdf_ratio.g + f.pdf_ratio.b) / 3) : f.weight;
            for (int c = 0; c < 3; ++c) {
                sums[std::size_t(c)] += double(w[c]);
                sums2[std::size_t(c)] += double(w[c]) * double(w[c]);
                largest = std::max(largest, double(w[c]));
            }
        }
        if (mis) {
            CHECK(largest <= 3 * (1 + 1e-6));
            for (int c = 0; c < 3; ++c) {
                const double mean = sums[std::size_t(c)] / n;
                const double error = std::sqrt((sums2[std::size_t(c)] / n - mean * mean) / n);
                const double exact = 1 - std::exp(-double(sigma_t[c]) * 4);
                INFO("channel " << c << ": " << mean << " +- " << error << ", exact " << exact);
                CHECK(std::abs(mean - exact) < 5 * error);
            }
        } else {
            // (σ_r / σ_b) e^((σ_b − σ_r) t): the blue channel's samples weigh red by e^(3.75 t) / 16, about
            // 10³ at the largest t of 200000 samples, and without bound as t_max grows.
            CHECK(largest > 300);
        }
    }
}

TEST_CASE("Absorbing fog: an emitter at distance d reads exp(-sigma_a d), camera rays and shadow rays",
          "[ex:ch02.plane][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch05.termination]"
          "[ex:ch06.path_tracer][ex:ch07.beer_lambert]") {
    // An emitter of radiance 1 at z = −5 facing the camera at the origin; fog of σ_a = 0.3 everywhere.
    const Scene seen = scene_from(R"({
      "camera": {"from": [0, 0, 0], "at": [0, 0, -1]},
      "medium": {"sigma_a": [0.3, 0.1, 0]},
      "materials": {"lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [1, 1, 1]}},
      "shapes": [{"type": "quad", "origin": [-50, -50, -5], "u": [100, 0, 0], "v": [0, 100, 0], "material": "lamp"}]
    })");
    CHECK(needed(seen).contains(Effect::kMedia));
    const Prepared p(seen);
    Pcg32 rng(1, 1);
    RayCounts rays;
    const Color L = p.tracer.radiance({{0, 0, 0}, {0, 0, -1}}, rng, rays);
    CHECK(L.r == Approx(std::exp(-1.5)).epsilon(1e-5));
    CHECK(L.g == Approx(std::exp(-0.5)).epsilon(1e-5));
    CHECK(L.b == 1);
    // A white floor under a point light 3 above it, seen from 4 away: the light crosses 3 units of fog to the
    // floor, the floor's light 4 to the camera: L = (ρ / π) (I / 9) e^(−0.3 · 7).
    const Scene lit = scene_from(R"({
      "camera": {"from": [0, 4, 0], "at": [0, 0, 0], "up": [0, 0, 1]},
      "medium": {"sigma_a": [0.3, 0.3, 0.3]},
      "materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
      "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"}],
      "lights": [{"type": "point", "position": [0, 3, 0], "intensity": [9, 9, 9]}]
    })");
    const Prepared q(lit);
    const Color floor = q.tracer.radiance({{0, 4, 0}, {0, -1, 0}}, rng, rays);
    CHECK(floor.g == Approx(0.5 / kPiD * std::exp(-0.3 * 7)).epsilon(1e-4));
}

TEST_CASE("An absorbing slab (index-matched) passes exp(-sigma_a thickness), to camera rays and shadow rays",
          "[ex:ch02.plane][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch05.termination]"
          "[ex:ch06.path_tracer][ex:ch07.beer_lambert]") {
    // A slab 2 thick between the camera and a floor, and between a point light and the floor, in absorbing
    // fog (σ_a = 0.01): with a medium in the scene, shadow rays carry transmittance across index-matched
    // boundaries.
    const Scene scene = scene_from(R"({
      "camera": {"from": [0, 10, 0], "at": [0, 0, 0], "up": [0, 0, 1]},
      "medium": {"sigma_a": [0.01, 0.01, 0.01]},
      "materials": {
        "slab": {"type": "dielectric", "ior": 1, "medium": {"sigma_a": [0.2, 0.5, 1]}},
        "white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}
      },
      "shapes": [
        {"type": "box", "min": [-100, 2, -100], "max": [100, 4, 100], "material": "slab"},
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"}
      ],
      "lights": [{"type": "point", "position": [0, 6, 0], "intensity": [36, 36, 36]}]
    })");
    const Prepared p(scene);
    Pcg32 rng(1, 1);
    RayCounts rays;
    // The floor straight below the camera: the light's way down (2 of slab, 4 of fog) and the floor's way up
    // (2 of slab, 8 of fog): L = (ρ / π) (I / 36) e^(−4 σ_slab − 12 σ_fog).
    const Color L = p.tracer.radiance({{0, 10, 0}, {0, -1, 0}}, rng, rays);
    for (int c = 0; c < 3; ++c) {
        const double sigma = c == 0 ? 0.2 : c == 1 ? 0.5 : 1;
        CHECK(L[c] == Approx(0.5 / kPiD * std::exp(-4 * sigma - 12 * 0.01)).epsilon(1e-4));
    }
}

// ---------------------------------------------------------------------------------------------------------
// White furnaces and energy

TEST_CASE(
    "Furnace: an index-matched sphere of albedo 1 under a sky of radiance 1 reads 1 at every pixel, g = 0 "
    "and 0.7",
    "[statistical][ex:ch01.camera_ray][ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch06.mis_weight]"
    "[ex:ch06.path_tracer][ex:ch06.uniform_sphere][ex:ch07.beer_lambert][ex:ch09.free_flight][ex:ch09.hg_"
    "sample]"
    "[ex:ch09.transmittance][ex:ch09.volume_vertex]") {
    for (Real g : {Real(0), Real(0.7)}) {
        const FurnaceCheck f = furnace({Color(0), Color(2), g}, 1, 2000);
        INFO("g = " << g << ": worst pixel " << f.worst_sigmas << " standard errors off, largest error "
                    << f.largest_error << ", mean " << f.mean);
        CHECK(f.worst_sigmas < 4.5);
        CHECK(f.largest_error < 0.02);
        CHECK(f.mean == Approx(1).margin(0.01));
    }
}

TEST_CASE(
    "Furnace: a sphere of ior 1.5 and albedo 1 under a sky of radiance 1 reads 1 at every pixel, g = 0 and "
    "0.7",
    "[statistical][ex:ch01.camera_ray][ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch05.termination]"
    "[ex:ch06.path_tracer][ex:ch06.uniform_sphere][ex:ch07.beer_lambert][ex:ch07.dielectric_sample][ex:ch07."
    "fresnel_exact]"
    "[ex:ch07.refract][ex:ch09.free_flight][ex:ch09.hg_sample][ex:ch09.transmittance][ex:ch09.volume_"
    "vertex]") {
    for (Real g : {Real(0), Real(0.7)}) {
        const FurnaceCheck f = furnace({Color(0), Color(2), g}, 1.5f, 2000);
        INFO("g = " << g << ": worst pixel " << f.worst_sigmas << " standard errors off, largest error "
                    << f.largest_error << ", mean " << f.mean);
        CHECK(f.worst_sigmas < 4.5);
        CHECK(f.largest_error < 0.03);
        CHECK(f.mean == Approx(1).margin(0.015));
    }
}

TEST_CASE(
    "Furnace: a chromatic medium of albedo 1 (sigma_s = 0.5, 2, 8) reads 1 in every channel",
    "[statistical][ex:ch01.camera_ray][ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch05.termination]"
    "[ex:ch06.path_tracer][ex:ch06.uniform_sphere][ex:ch07.beer_lambert][ex:ch07.dielectric_sample][ex:ch07."
    "fresnel_exact]"
    "[ex:ch07.refract][ex:ch09.free_flight][ex:ch09.hg_sample][ex:ch09.transmittance][ex:ch09.volume_"
    "vertex]") {
    const std::vector<FurnaceCheck> channels =
        furnace_channels({Color(0), Color(0.5f, 2, 8), 0.3f}, 1.5f, 2000);
    for (int channel = 0; channel < 3; ++channel) {
        const FurnaceCheck& f = channels[std::size_t(channel)];
        INFO("channel " << channel << ": worst pixel " << f.worst_sigmas
                        << " standard errors off, largest error " << f.largest_error << ", mean " << f.mean);
        CHECK(f.worst_sigmas < 4.5);
        CHECK(f.largest_error < 0.04);
        CHECK(f.mean == Approx(1).margin(0.02));
    }
}

TEST_CASE(
    "Energy: a medium of albedo 0.8 never returns more than the furnace gives in",
    "[statistical][ex:ch01.camera_ray][ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch05.termination]"
    "[ex:ch06.path_tracer][ex:ch06.uniform_sphere][ex:ch07.beer_lambert][ex:ch07.dielectric_sample][ex:ch07."
    "fresnel_exact]"
    "[ex:ch07.refract][ex:ch09.free_flight][ex:ch09.hg_sample][ex:ch09.transmittance][ex:ch09.volume_"
    "vertex]") {
    const Prepared p(medium_sphere_scene({Color(0.4f), Color(1.6f), 0.5f}, 1.5f));
    const PinholeCamera camera = make_pinhole_camera(p.scene.camera, 6, 6);
    for (int y = 0; y < 6; ++y) {
        for (int x = 0; x < 6; ++x) {
            const Estimate e = estimate(p.tracer, camera_ray(camera, Real(x) + 0.5f, Real(y) + 0.5f), 1000,
                                        std::uint64_t(y * 6 + x));
            CHECK(e.mean <= 1 + 4 * e.error);
        }
    }
    // Straight at the centre it is clearly darker.
    const Estimate centre = estimate(p.tracer, {{0, 0, 4}, {0, 0, -1}}, 4000, 99);
    CHECK(centre.mean + 5 * centre.error < 0.9);
}

// ---------------------------------------------------------------------------------------------------------
// Slabs: single scattering, and all orders in a semi-infinite medium

TEST_CASE(
    "Single scattering in a slab of optical thickness 1 (albedo 1, isotropic, index-matched): R1 = 0.14202 "
    "and T1 = 0.10617, by quadrature and by the walk cut after one event",
    "[statistical][ex:ch02.plane][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch06.mis_weight]"
    "[ex:ch06.path_tracer][ex:ch06.uniform_sphere][ex:ch07.beer_lambert][ex:ch09.free_flight]"
    "[ex:ch09.hg_sample][ex:ch09.transmittance][ex:ch09.volume_vertex]") {
    // R1 = (ω/2) ∫₀¹ μ/(1+μ) (1 − e^(−τ(1+1/μ))) dμ, T1 = (ω/2) ∫₀¹ μ (e^(−τ) − e^(−τ/μ)) / (1 − μ) dμ.
    std::vector<double> mu, w;
    gauss_legendre(200, mu, w);
    const double tau = 1, omega = 1;
    double R1 = 0, T1 = 0;
    for (std::size_t i = 0; i < mu.size(); ++i) {
        R1 += w[i] * omega / 2 * mu[i] / (1 + mu[i]) * (1 - std::exp(-tau * (1 + 1 / mu[i])));
        T1 += w[i] * omega / 2 * mu[i] * (std::exp(-tau) - std::exp(-tau / mu[i])) / (1 - mu[i]);
    }
    CHECK(R1 == Approx(0.14202).margin(1e-5));
    CHECK(T1 == Approx(0.10617).margin(1e-5));
    const Prepared p(medium_slab_scene({Color(0), Color(1), 0}, 1), {}, MediumWalk{1, true});
    // Straight down from above (what the slab reflects; the black floor takes what passes), and straight up
    // from below it (the sky seen through it, e^−τ unscattered, and what it scatters down once).
    const Estimate R = estimate(p.tracer, {{0, 2, 0}, {0, -1, 0}}, 50000, 1);
    const Estimate T = estimate(p.tracer, {{0, -1, 0}, {0, 1, 0}}, 50000, 2);
    INFO("R " << R.mean << " +- " << R.error << ", T " << T.mean << " +- " << T.error);
    CHECK(std::abs(R.mean - R1) < 4.5 * R.error);
    CHECK(std::abs(T.mean - (std::exp(-tau) + T1)) < 4.5 * T.error);
    CHECK(R.error < 2e-3);
    CHECK(T.error < 2e-3);
}

TEST_CASE(
    "Semi-infinite medium, all orders: A(1) = 1 - H(1) sqrt(1 - omega) with Chandrasekhar's H, for omega = "
    "0.5, 0.9 and 0.99",
    "[statistical][ex:ch02.plane][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch06.mis_weight]"
    "[ex:ch06.path_tracer][ex:ch06.uniform_sphere][ex:ch07.beer_lambert][ex:ch09.free_flight]"
    "[ex:ch09.hg_sample][ex:ch09.transmittance][ex:ch09.volume_vertex]") {
    const double expected[] = {0.11523, 0.41495, 0.75272};
    int k = 0;
    for (double omega : {0.5, 0.9, 0.99}) {
        const HFunction H = chandrasekhar_h(omega);
        INFO("omega = " << omega);
        CHECK(H.moment() == Approx(2 / omega * (1 - std::sqrt(1 - omega))).epsilon(1e-9));
        const double A = 1 - H(1) * std::sqrt(1 - omega);
        CHECK(A == Approx(expected[k]).margin(1e-5));
        // A slab of optical thickness 40 over a black floor: by reciprocity the radiance seen straight down
        // under a sky of radiance 1 is the plane albedo at normal incidence.
        const Prepared p(medium_slab_scene({Color(Real(1 - omega)), Color(Real(omega)), 0}, 40));
        const Estimate e = estimate(p.tracer, {{0, 41, 0}, {0, -1, 0}}, 8000, 3 + std::uint64_t(k));
        INFO("walk " << e.mean << " +- " << e.error << ", A(1) " << A);
        CHECK(std::abs(e.mean - A) < 4.5 * e.error);
        CHECK(e.error < 0.01);
        ++k;
    }
}

// ---------------------------------------------------------------------------------------------------------
// Extremes, scenes, effects

TEST_CASE("No NaN or infinity at g = +-0.999, sigma = 1e-6 and sigma = 1e6",
          "[stability][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.sphere_stable][ex:ch03.robust_"
          "offset][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch06.uniform_sphere][ex:"
          "ch07.beer_lambert][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract][ex:ch09."
          "free_flight][ex:ch09.hg_sample][ex:ch09.transmittance][ex:ch09.volume_vertex]") {
    struct Case {
        MediumDesc medium;
        Real ior;
    };
    const std::vector<Case> cases = {
        {{Color(0), Color(2), 0.999f}, 1.5f},       {{Color(0), Color(2), -0.999f}, 1},
        {{Color(1e-6f), Color(1e-6f), 0.5f}, 1.5f}, {{Color(0), Color(1e-6f, 1, 1e6f), 0}, 1},
        {{Color(1e6f), Color(1e6f), -0.5f}, 1.5f},  {{Color(0), Color(1e6f), 0.9f}, 1},
    };
    const RenderSettings settings = small_render(8, 4, 3);
    for (const Case& c : cases) {
        const Scene scene = medium_sphere_scene(c.medium, c.ior);
        const EffectSet simulated = simulated_effects(scene, kMediaChapterEffects);
        const RenderResult r =
            render_with_media(choose_renderer(simulated), scene, simulated, settings, {}, {2000, true});
        INFO("sigma_s " << c.medium.sigma_s.g << ", g " << c.medium.g << ", ior " << c.ior);
        CHECK(r.image.all_finite());
        CHECK(r.image.mean() <= 1.5);
    }
}

TEST_CASE("A medium lit only by scattering is lit: fog under a point light or a lamp, milk under a lamp",
          "[effects][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight]"
          "[ex:ch06.path_tracer][ex:ch07.beer_lambert][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:"
          "ch07.refract]"
          "[ex:ch09.free_flight][ex:ch09.hg_sample][ex:ch09.transmittance][ex:ch09.volume_vertex]") {
    // As a user's scene file is rendered: simulating simulated_effects(scene, supported). Before media called
    // for lighting these rendered black (fog under a point light: 0 shadow rays), or only what glass
    // reflects.
    const std::string camera = R"("camera": {"from": [0, 0, 5], "at": [0, 0, 0]},)";
    const std::string fog = R"("medium": {"sigma_a": [0.01, 0.01, 0.01], "sigma_s": [0.2, 0.2, 0.2]},)";
    const std::string lamp = R"({"type": "quad", "origin": [-1, 3, -1], "u": [2, 0, 0], "v": [0, 0, 2],
                                 "material": "lamp"})";
    const std::string lamp_material =
        R"("lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [10, 10, 10]})";
    const std::vector<std::string> scenes = {
        "{" + camera + fog +
            R"("lights": [{"type": "point", "position": [0, 0, 0], "intensity": [10, 10, 10]}]})",
        "{" + camera + fog + R"("materials": {)" + lamp_material + R"(}, "shapes": [)" + lamp + "]}",
        "{" + camera + R"("materials": {)" + lamp_material +
            R"(, "milk": {"type": "dielectric", "ior": 1.3, "medium": {"sigma_a": [0.01, 0.01, 0.01],
               "sigma_s": [3, 3, 3]}}}, "shapes": [)" +
            lamp + R"(, {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "milk"}]})"};
    const RenderSettings settings = small_render(16, 16, 2);
    for (const std::string& text : scenes) {
        const Scene scene = scene_from(text);
        const EffectSet simulated = simulated_effects(scene, kMediaChapterEffects);
        INFO(text << "\nsimulated: " << simulated.to_string());
        const RenderResult r = render_with_media(choose_renderer(simulated), scene, simulated, settings);
        const RenderResult every =
            render_with_media(choose_renderer(EffectSet::all()), scene, EffectSet::all(), settings);
        CHECK(r.rays[RayKind::kShadow] > 0);
        // The same image as with every effect simulated: here the same random numbers, so the same bits.
        CHECK(r.image.pixels() == every.image.pixels());
        CHECK(r.image.mean() > 0.05);
    }
}

TEST_CASE("Scene format: media inside dielectrics and between the shapes, what they call for, and refusals",
          "") {
    const std::string camera = R"("camera": {"from": [0, 0, 4], "at": [0, 0, 0]},)";
    const Scene milk = scene_from("{" + camera + R"(
      "materials": {"milk": {"type": "dielectric", "ior": 1.3, "medium": {"sigma_a": [0.1, 0.2, 0.3], "sigma_s": [1, 2, 3], "g": 0.5}}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "milk"}]})");
    REQUIRE(milk.materials[0].medium);
    CHECK(milk.materials[0].medium->sigma_t() == Color(1.1f, 2.2f, 3.3f));
    CHECK(milk.materials[0].medium->g == 0.5f);
    CHECK(needed(milk).contains(Effect::kMedia));
    const Scene amber = scene_from("{" + camera + R"(
      "materials": {"amber": {"type": "dielectric", "medium": {"sigma_a": [0.1, 0.2, 0.3]}}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "amber"}]})");
    CHECK_FALSE(needed(amber).contains(Effect::kMedia));  // it only absorbs: chapter 07's Beer–Lambert
    const Scene fog = scene_from("{" + camera + R"("medium": {"sigma_a": [0.01, 0.01, 0.01]},
      "materials": {"white": {"type": "diffuse"}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "white"}]})");
    REQUIRE(fog.medium);
    CHECK(needed(fog).contains(Effect::kMedia));
    const auto refused = [&](const std::string& materials, const std::string& top,
                             const std::string& message) {
        const std::string json =
            "{" + camera + top + R"("materials": {"m": )" + materials +
            R"(}, "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
        CHECK_THROWS_WITH(scene_from(json), message);
    };
    refused(R"({"type": "dielectric", "medium": {"sigma_s": [1, -1, 1]}})", "",
            "test.json: materials.m.medium.sigma_s[1]: must be in [0, 1e+09], got -1");
    refused(R"({"type": "dielectric", "medium": {"g": 1}})", "",
            "test.json: materials.m.medium.g: must be in (-1, 1), got 1");
    refused(R"({"type": "diffuse", "medium": {"sigma_s": [1, 1, 1]}})", "",
            "test.json: materials.m.medium: only a dielectric material holds a medium (its shapes' inside), "
            "got a "
            "diffuse material");
    refused(R"({"type": "dielectric", "absorption": [1, 1, 1], "medium": {"sigma_s": [1, 1, 1]}})", "",
            "test.json: materials.m.medium: give either absorption or medium (a medium's sigma_a is its "
            "absorption)");
    refused(R"({"type": "diffuse"})", R"("medium": {"sigma_a": [1, 1, 1], "sigma": 2},)",
            "test.json: medium.sigma: unknown key for a medium (did you mean \"sigma_a\"?)");
    refused(R"({"type": "diffuse"})", R"("medium": {"g": -1.5},)",
            "test.json: medium.g: must be in (-1, 1), got -1.5");
}

TEST_CASE(
    "Without media a scattering medium is Beer-Lambert absorption by sigma_a + sigma_s, with its note, and "
    "fog is empty space",
    "[ex:ch07.beer_lambert]") {
    const Scene scene = scene_from(R"({
      "camera": {"from": [0, 0, 4], "at": [0, 0, 0]},
      "medium": {"sigma_s": [0.5, 0.5, 0.5]},
      "materials": {"milk": {"type": "dielectric", "ior": 1, "medium": {"sigma_a": [0.1, 0.1, 0.1], "sigma_s": [1, 2, 3]}}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "milk"}]
    })");
    const EffectSet without_media = EffectSet::all().without({Effect::kMedia});
    const MaterialTable table(scene, without_media, media_materials());
    REQUIRE(table.interior(0));
    CHECK_FALSE(dynamic_cast<const ScatteringMedium*>(table.interior(0)));
    CHECK(table.interior(0)->transmittance(1).b == Approx(std::exp(-3.1)).epsilon(1e-6));
    CHECK(table.exterior() == nullptr);
    REQUIRE(table.notes().size() == 2);
    CHECK(table.notes()[0] ==
          "dielectric material 'milk': its medium: media is not simulated in this run (chapter 09 adds it); "
          "treated "
          "as Beer-Lambert absorption by sigma_a + sigma_s");
    CHECK(table.notes()[1] ==
          "medium between the shapes: media is not simulated in this run (chapter 09 adds it); treated as "
          "empty "
          "space");
    // With media: the homogeneous medium inside and between the shapes, no notes.
    const MaterialTable with(scene, EffectSet::all(), media_materials());
    REQUIRE(with.interior(0));
    CHECK(dynamic_cast<const ScatteringMedium*>(with.interior(0)));
    CHECK(with.exterior());
    CHECK(with.notes().empty());
    // Chapter 07's table (no media hook) is the same as without media.
    const MaterialTable ch07(scene, EffectSet::all(), refraction_materials());
    CHECK_FALSE(dynamic_cast<const ScatteringMedium*>(ch07.interior(0)));
    CHECK(ch07.exterior() == nullptr);
}

TEST_CASE("The default scene renders finite and calls for media",
          "[ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight]"
          "[ex:ch06.path_tracer][ex:ch07.beer_lambert][ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:"
          "ch07.refract]"
          "[ex:ch09.free_flight][ex:ch09.hg_sample][ex:ch09.transmittance][ex:ch09.volume_vertex]") {
    const Scene scene = load_scene(scene_path("ch09_default.json"));
    CHECK(needed(scene).contains(Effect::kMedia));
    const RenderSettings settings = small_render(16, 2, 1);
    const EffectSet simulated = simulated_effects(scene, kMediaChapterEffects);
    const RenderResult r = render_with_media(choose_renderer(simulated), scene, simulated, settings);
    CHECK(r.image.all_finite());
    CHECK(r.image.mean() > 0.02);
}

TEST_CASE("Without media the volumetric loop is chapter 06's to the bit, and the run is chapter 07's render",
          "[ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]"
          "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    // The glass box: glass, a lamp, diffuse walls; each strategy and sampler draws its numbers its own way.
    const Scene scene = load_scene(scene_path("cornell.json"));
    REQUIRE_FALSE(needed(scene).contains(Effect::kMedia));
    const EffectSet simulated = simulated_effects(scene, kMediaChapterEffects);
    const RenderSettings settings = small_render(24, 4, 5);
    for (const SamplingStrategy strategy : {SamplingStrategy::kMis, SamplingStrategy::kLight}) {
        for (const PointSet sampler : {PointSet::kStratified, PointSet::kSobol}) {
            PathOptions options;
            options.strategy = strategy;
            options.sampler = sampler;
            const RenderResult ch06 = render_with(Renderer::kPaths, scene, simulated, settings, options);
            // This chapter's loop itself (render_with_media hands such a run to chapter 07's, below).
            const Prepared volumetric(scene, options);
            const RenderResult ch09 =
                render_paths(volumetric.tracer,
                             make_pinhole_camera(scene.camera, settings.width, settings.height), settings);
            CHECK(ch06.image.pixels() == ch09.image.pixels());
            CHECK(ch06.rays.total() == ch09.rays.total());
            const RenderResult handed_over =
                render_with_media(Renderer::kPaths, scene, simulated, settings, options);
            CHECK(handed_over.image.pixels() == ch06.image.pixels());
        }
    }
    PathOptions options;
    options.simulated = simulated;
    CHECK(media_notes(scene, Renderer::kPaths, options, {}).front() ==
          "renderer: paths (chapter 06's loop, chapter 07's BSDFs: the scene calls for no media)");
    // With media the volumetric loop runs, and says so.
    const Scene fog = load_scene(scene_path("ch09_default.json"));
    options.simulated = simulated_effects(fog, kMediaChapterEffects);
    REQUIRE(options.simulated.contains(Effect::kMedia));
    CHECK(media_notes(fog, Renderer::kPaths, options, {}).front() ==
          "renderer: paths (chapter 09's volumetric loop, chapter 07's BSDFs)");
}

TEST_CASE(
    "The most complete renderer: chapter 08's combined tracer where mirrors or glass cast caustics, "
    "paths elsewhere, and the summary says why",
    "[ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
    "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
    "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]"
    "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract][ex:ch08.connect]"
    "[ex:ch08.pinhole_importance][ex:ch08.project_direction]") {
    const RenderSettings settings = small_render(16, 4, 9);
    // Why a scene gets the tracer it gets (the summary's first line ends with it).
    const auto because = [&](const Scene& scene) {
        const TracerChoice choice = choose_tracer(
            TracerRule::kAuto, {scene, settings, simulated_effects(scene, kMediaChapterEffects)});
        return std::string(choice.combined ? "combined: " : "paths: ") + choice.because;
    };
    const std::string caustics =
        "mirrors or smooth glass lit by area or point lights: light paths find the "
        "caustics the camera sees (chapter 08)";
    CHECK(because(load_scene(scene_path("ch08_mirror.json"))) == "combined: " + caustics);
    // Under a depth cap (the scene's max_depth or --max-depth) camera paths alone: light paths count their
    // bounces from the light, and would not end where the cap says.
    const Scene mirror = load_scene(scene_path("ch08_mirror.json"));
    const TracerChoice capped =
        choose_tracer(TracerRule::kAuto, {mirror, settings, simulated_effects(mirror, kMediaChapterEffects)},
                      {.termination = true});
    CHECK_FALSE(capped.combined);
    CHECK(capped.because ==
          "a depth or a termination rule is set, and light paths count bounces from the light");
    CHECK(because(load_scene(scene_path("suite_diffuse.json"))) ==
          "paths: no mirror or smooth glass: no caustic for light paths to find");
    // In fog, Cycles' volume sampling, where the flags leave it open; inside a shape (the milk), the flags'.
    CHECK(because(load_scene(scene_path("ch09_default.json"))) ==
          "paths: light paths cross no medium (chapter 08)");
    const Scene fog = load_scene(scene_path("ch09_thin_fog.json"));
    CHECK(because(fog) ==
          "paths: light paths cross no medium (chapter 08); in the fog, equiangular points "
          "by MIS and quad lights by solid angle, as Cycles samples volumes");
    const RunContext fog_run{fog, settings, simulated_effects(fog, kMediaChapterEffects)};
    const TracerChoice chosen_for_fog = choose_tracer(TracerRule::kAuto, fog_run);
    CHECK(chosen_for_fog.distance == DistanceSampling::kMis);
    CHECK(chosen_for_fog.quad_lights == QuadLightSampling::kSolidAngle);
    const TracerChoice kept = choose_tracer(TracerRule::kAuto, fog_run, {.distance_sampling = true});
    CHECK_FALSE(kept.distance);
    CHECK(kept.because ==
          "light paths cross no medium (chapter 08); in the fog, quad lights by solid angle, as "
          "Cycles samples volumes");
    const TracerChoice as_given = choose_tracer(TracerRule::kPaths, fog_run);
    CHECK_FALSE(as_given.distance);
    CHECK_FALSE(as_given.quad_lights);

    // The glass box: the image is the combined tracer's, to the bit, and chapter 08's summary follows.
    Scene glass = load_scene(scene_path("cornell.json"));
    const EffectSet simulated = simulated_effects(glass, kMediaChapterEffects);
    const ChapterRun chosen = render_by_choice(TracerRule::kAuto, {glass, settings, simulated}, {}, {});
    CHECK(chosen.notes.front() == "strategy: combined, because " + caustics);
    CHECK(chosen.notes.at(1).starts_with("tracer: combined; chapter 06's paths (sampler sobol"));
    CombinedOptions options;
    const CombinedResult direct = render_combined(glass, simulated, settings, options);
    REQUIRE(direct.split);
    CHECK(chosen.result.image.pixels() == direct.render.image.pixels());
    CHECK(chosen.result.rays.total() == direct.render.rays.total());
    // --tracer paths: chapter 07's render, as before the choice.
    const ChapterRun paths = render_by_choice(TracerRule::kPaths, {glass, settings, simulated}, {}, {});
    CHECK(paths.notes.front() == "strategy: paths, because --tracer paths asks for them");
    PathOptions path_options;
    path_options.simulated = simulated;
    CHECK(paths.result.image.pixels() ==
          render_with_media(Renderer::kPaths, glass, simulated, settings, path_options).image.pixels());
    // A piece of a split render is refused before it renders: it would not merge into the whole's bits.
    RenderSettings piece = settings;
    piece.samples = SampleRange{0, 2};
    CHECK_THROWS_WITH(
        render_by_choice(TracerRule::kAuto, {glass, piece, simulated}, {}, {}),
        Catch::Contains("--samples (or MPI ranks): this scene's caustics are rendered by the "
                        "combined tracer, which renders whole; --tracer paths renders in pieces"));
    CHECK(render_by_choice(TracerRule::kPaths, {glass, piece, simulated}, {}, {}).result.image.all_finite());
    // A lens: light paths reach a pinhole, which would change the picture.
    glass.camera.aperture = 5;
    CHECK(because(glass) == "paths: light paths reach a pinhole, and this camera has a lens");
}

// ---------------------------------------------------------------------------------------------------------
// Equiangular distance sampling (equiangular.hpp, distance_sampling.hpp).

namespace {

// The density in double, from its definition: D / ((θ_b − θ_a)(D² + (t − Δ)²)), θ = atan((t − Δ) / D).
double equiangular_pdf_exact(double delta, double d, double t_max, double t) {
    const double width = std::atan((t_max - delta) / d) - std::atan(-delta / d);
    return d / (width * (d * d + (t - delta) * (t - delta)));
}
// Its CDF, for the chi-square cells.
double equiangular_cdf_exact(double delta, double d, double t_max, double t) {
    const double a = std::atan(-delta / d), b = std::atan((t_max - delta) / d);
    return (std::atan((t - delta) / d) - a) / (b - a);
}

// The naive sampler of the paper, in the course's float: D = √(|x_l − o|² − Δ²), θ_a and θ_b as two atans.
struct NaiveEquiangular {
    Real delta, d, theta_a, theta_b;
    NaiveEquiangular(const Ray& ray, const Vec3& x, Real t_max) {
        delta = glm::dot(x - ray.origin, ray.direction);
        d = std::sqrt(glm::dot(x - ray.origin, x - ray.origin) - delta * delta);
        theta_a = std::atan(-delta / d);
        theta_b = std::atan((t_max - delta) / d);
    }
    Real sample(Real u) const { return delta + d * std::tan(theta_a + u * (theta_b - theta_a)); }
    Real pdf(Real t) const { return d / ((theta_b - theta_a) * (d * d + (t - delta) * (t - delta))); }
};

}  // namespace

TEST_CASE("Equiangular sampling fits its pdf by chi-square: the light over the segment, past its end, behind",
          "[equiangular]") {
    // Δ inside [0, t_max), beyond it and behind the origin: 200 cells of equal width, each expecting
    // N (F(t_1) − F(t_0)) from the closed-form CDF, through the shared harness (cells pooled to >= 5).
    struct Case {
        double delta, d, t_max;
    };
    const std::vector<Case> cases = {{3, 0.5, 10}, {15, 2, 10}, {-4, 1, 10}};
    const int n = 1000000, cells = 200;
    for (const Case& c : cases) {
        const Ray ray{{0, 0, 0}, {0, 0, 1}};
        const Vec3 light{Real(c.d), 0, Real(c.delta)};
        const auto sampler = EquiangularSampler::toward(ray, light, Real(c.t_max));
        REQUIRE(sampler);
        std::vector<double> observed(cells, 0), expected(cells, 0);
        Pcg32 rng(7, 17);
        long long bad = 0;
        for (int i = 0; i < n; ++i) {
            const Real t = sampler->sample(rng.next_real());
            if (!(t >= 0 && t < Real(c.t_max)) || !(sampler->pdf(t) > 0)) {
                ++bad;
                continue;
            }
            observed[std::min(cells - 1, int(double(t) / c.t_max * cells))] += 1;
        }
        for (int k = 0; k < cells; ++k)
            expected[k] = n * (equiangular_cdf_exact(c.delta, c.d, c.t_max, c.t_max * (k + 1) / cells) -
                               equiangular_cdf_exact(c.delta, c.d, c.t_max, c.t_max * k / cells));
        const test::ChiSquare r = test::chi_square(observed, expected);
        INFO("delta " << c.delta << ", D " << c.d << ": chi-square " << r.statistic << ", " << r.dof
                      << " dof, p = " << r.p_value);
        CHECK(bad == 0);
        CHECK(r.p_value > test::sidak_level(3));
    }
}

TEST_CASE("The equiangular pdf integrates to 1 over the segment and is the closed form", "[equiangular]") {
    // Trapezoids on 2·10⁶ nodes (the narrowest peak, D = 0.01, spans 10³ of them), in double over the
    // float pdf; and pointwise against the definition in double.
    struct Case {
        double delta, d, t_max;
    };
    for (const Case c : {Case{5, 0.01, 10}, Case{3, 0.5, 10}, Case{500, 1e-3, 100}, Case{-4, 1, 10}}) {
        const auto sampler =
            EquiangularSampler::toward({{0, 0, 0}, {0, 0, 1}}, {Real(c.d), 0, Real(c.delta)}, Real(c.t_max));
        REQUIRE(sampler);
        const int n = 2000000;
        double sum = 0;
        for (int i = 0; i <= n; ++i) {
            const double t = std::min(c.t_max * i / n, double(std::nextafter(Real(c.t_max), Real(0))));
            sum += (i == 0 || i == n ? 0.5 : 1.0) * double(sampler->pdf(Real(t)));
        }
        INFO("delta " << c.delta << ", D " << c.d << ", t_max " << c.t_max);
        CHECK(sum * c.t_max / n == Approx(1).epsilon(2e-3));
        for (double t : {0.0, c.t_max / 3, c.delta, c.t_max * 0.99})
            if (t >= 0 && t < c.t_max)
                CHECK(double(sampler->pdf(Real(t))) ==
                      Approx(equiangular_pdf_exact(c.delta, c.d, c.t_max, t)).epsilon(1e-3));
        CHECK(sampler->pdf(Real(-1)) == 0);
        CHECK(sampler->pdf(Real(c.t_max)) == 0);
    }
}

TEST_CASE(
    "Equiangular sampling with the light on or very near the ray's line: the naive form is NaN, the "
    "robust one holds",
    "[equiangular]") {
    const Ray ray{{0, 0, 0}, {0, 0, 1}};
    // A light 10⁻³ off the line, 500 units ahead of a segment 100 long: |x_l − o|² − Δ² cancels to 0 in
    // float, and θ_a = θ_b = −π/2: the naive density is 0 / 0.
    {
        const Vec3 light{1e-3f, 0, 500};
        const NaiveEquiangular naive(ray, light, 100);
        CHECK(!std::isfinite(naive.pdf(naive.sample(0.5f))));
        const auto robust = EquiangularSampler::toward(ray, light, 100);
        REQUIRE(robust);
        CHECK(double(robust->distance()) == Approx(1e-3).epsilon(1e-3));
        for (Real u : {0.0f, 0.25f, 0.5f, 0.999f}) {
            const Real t = robust->sample(u);
            CHECK((t >= 0 && t < 100));
            // u = F(t): the CDF of 1 / (t − Δ)² on [0, 100), Δ = 500: F(t) = (1 / (Δ − t) − 1 / Δ) / (1 / 400
            // − 1 / 500).
            CHECK((1 / (500.0 - t) - 1 / 500.0) / (1 / 400.0 - 1 / 500.0) == Approx(u).margin(1e-4));
            CHECK(double(robust->pdf(t)) == Approx(equiangular_pdf_exact(500, 1e-3, 100, t)).epsilon(1e-3));
        }
    }
    // A light 10⁻⁶ off the line inside the segment, 50 units ahead: the naive D is 0 (or the root of a
    // negative number) and its samples all sit at Δ with density 0 / 0; the robust one keeps D and a peak of
    // height 1 / (π D).
    {
        const Vec3 light{1e-6f, 0, 50};
        const NaiveEquiangular naive(ray, light, 100);
        CHECK(!std::isfinite(naive.pdf(naive.sample(0.3f))));
        const auto robust = EquiangularSampler::toward(ray, light, 100);
        REQUIRE(robust);
        const Real t = robust->sample(0.3f);
        CHECK((t >= 0 && t < 100));
        CHECK(std::isfinite(robust->pdf(t)));
        CHECK(double(robust->pdf(50)) == Approx(1 / (kPiD * 1e-6)).epsilon(1e-3));
    }
    // On the line, and segments that are not finite and positive: no sampler (the caller keeps free flight).
    CHECK(!EquiangularSampler::toward(ray, {0, 0, 50}, 100));
    CHECK(!EquiangularSampler::toward(ray, {1, 0, 50}, kInfinity));
    CHECK(!EquiangularSampler::toward(ray, {1, 0, 50}, 0));
}

namespace {

// Single scattering from a point light of intensity I at x_l into a ray through a homogeneous isotropic
// medium, up to a black wall at t_max:
//   L = ∫_0^t_max e^(−σ_t t) σ_s (1 / 4π) I e^(−σ_t r(t)) / r(t)² dt,   r(t) = |x(t) − x_l|,
// with t = Δ + D tan θ (dt = r² / D dθ) a smooth integral in θ, by 64-point Gauss–Legendre on 64 panels.
double single_scattering_exact(double sigma_s, double sigma_t, double intensity, double delta, double d,
                               double t_max) {
    std::vector<double> x, w;
    gauss_legendre(64, x, w);
    const double a = std::atan(-delta / d), b = std::atan((t_max - delta) / d);
    const int panels = 64;
    double sum = 0;
    for (int p = 0; p < panels; ++p)
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double theta = a + (b - a) * (p + x[i]) / panels;
            const double t = delta + d * std::tan(theta), r = d / std::cos(theta);
            sum += w[i] * (b - a) / panels * std::exp(-sigma_t * (t + r));
        }
    return sigma_s * intensity / (4 * kPiD * d) * sum;
}

// The same for a square lamp of side 2 and radiance Le, facing down at height 1 over the ray's line, centred
// above t = delta (g = 0): ∫ e^(−σ_t t) σ_s ∫_A Le / (4π) e^(−σ_t r) cos θ_l / r² dA dt, cos θ_l = 1 / r, by
// Gauss–Legendre in t and over the square.
double single_scattering_square_exact(double sigma_s, double sigma_t, double radiance, double delta,
                                      double t_max) {
    std::vector<double> x, w;
    gauss_legendre(16, x, w);
    const int t_panels = 64, a_panels = 16;
    double sum = 0;
    for (int p = 0; p < t_panels; ++p)
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double t = t_max * (p + x[i]) / t_panels, wt = w[i] * t_max / t_panels;
            double lamp = 0;
            for (int pa = 0; pa < a_panels; ++pa)
                for (int pb = 0; pb < a_panels; ++pb)
                    for (std::size_t j = 0; j < x.size(); ++j)
                        for (std::size_t k = 0; k < x.size(); ++k) {
                            const double lx = -1 + 2 * (pa + x[j]) / a_panels;
                            const double lz = -1 + 2 * (pb + x[k]) / a_panels;
                            const double dz = (delta - t) - lz;  // along the ray's line
                            const double r2 = lx * lx + 1 + dz * dz, r = std::sqrt(r2);
                            lamp += w[j] * w[k] * (4.0 / (a_panels * a_panels)) * std::exp(-sigma_t * r) /
                                    (r2 * r);
                        }
            sum += wt * std::exp(-sigma_t * t) * lamp;
        }
    return sigma_s * radiance / (4 * kPiD) * sum;
}

}  // namespace

TEST_CASE(
    "Single scattering of a point light in fog, each --distance-sampling against the exact integral",
    "[equiangular][ex:ch01.camera_ray][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
    "[ex:ch04.lambert][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer][ex:ch07.beer_lambert]"
    "[ex:ch09.free_flight][ex:ch09.hg_sample][ex:ch09.transmittance][ex:ch09.volume_vertex]") {
    // A scene file as a user writes it: fog, a point light 1 unit off the camera's axis, a black wall 10
    // units ahead; "effects" without indirect, so paths end at their second vertex: the image is single
    // scattering exactly.
    const Scene scene = scene_from(R"({
        "camera": {"from": [0, 0, 5], "at": [0, 0, 0]},
        "medium": {"sigma_a": [0.02, 0.02, 0.02], "sigma_s": [0.1, 0.1, 0.1], "g": 0},
        "lights": [{"type": "point", "position": [0, 1, 0], "intensity": [10, 10, 10]}],
        "materials": {"black": {"type": "diffuse", "albedo": [0, 0, 0]}},
        "shapes": [{"type": "quad", "origin": [-50, -50, -5], "u": [100, 0, 0], "v": [0, 100, 0],
                    "material": "black"}],
        "effects": ["camera", "shadows", "direct", "media"]})");
    const double exact = single_scattering_exact(0.1, 0.12, 10, 5, 1, 10);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, 1, 1);
    const Ray ray = camera_ray(camera, 0.5f, 0.5f);
    double error_free_flight = 0;
    for (const DistanceSampling s :
         {DistanceSampling::kFreeFlight, DistanceSampling::kEquiangular, DistanceSampling::kMis}) {
        MediumWalk walk;
        walk.distance = s;
        const Prepared p(scene, {}, walk);
        REQUIRE(!p.simulated.contains(Effect::kIndirect));
        const Estimate e = estimate(p.tracer, ray, 40000, 5);
        INFO(to_string(s) << ": " << e.mean << " ± " << e.error << ", exact " << exact);
        CHECK(std::abs(e.mean - exact) < 4 * e.error);
        CHECK(e.error < 0.01 * exact);
        if (s == DistanceSampling::kFreeFlight) error_free_flight = e.error;
        // Toward the light the error falls: equiangular's estimate is nearly the integrand's shape.
        if (s != DistanceSampling::kFreeFlight) CHECK(e.error < 0.5 * error_free_flight);
    }
}

TEST_CASE(
    "Single scattering of a square lamp in fog, with quad lights by area and by solid angle, each "
    "--distance-sampling against the exact integral",
    "[equiangular][ex:ch01.camera_ray][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
    "[ex:ch04.lambert][ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight]"
    "[ex:ch06.path_tracer][ex:ch07.beer_lambert][ex:ch09.free_flight][ex:ch09.hg_sample][ex:ch09."
    "transmittance]"
    "[ex:ch09.volume_vertex]") {
    // The point-light scene above with a 2×2 lamp 1 unit over the camera's axis, centred above t = 5: close
    // and wide, so a point on it by area and the direction by solid angle are far apart. The equiangular
    // target is a point by area under either; its density must be the one its sampler drew t with.
    const Scene scene = scene_from(R"({
        "camera": {"from": [0, 0, 5], "at": [0, 0, 0]},
        "medium": {"sigma_a": [0.02, 0.02, 0.02], "sigma_s": [0.1, 0.1, 0.1], "g": 0},
        "materials": {"black": {"type": "diffuse", "albedo": [0, 0, 0]},
                      "lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [10, 10, 10]}},
        "shapes": [{"type": "quad", "origin": [-50, -50, -5], "u": [100, 0, 0], "v": [0, 100, 0],
                    "material": "black"},
                   {"type": "quad", "origin": [-1, 1, -1], "u": [2, 0, 0], "v": [0, 0, 2], "material": "lamp"}],
        "effects": ["camera", "shadows", "direct", "media"]})");
    const double exact = single_scattering_square_exact(0.1, 0.12, 10, 5, 10);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, 1, 1);
    const Ray ray = camera_ray(camera, 0.5f, 0.5f);
    for (const QuadLightSampling quads : {QuadLightSampling::kArea, QuadLightSampling::kSolidAngle})
        for (const DistanceSampling s :
             {DistanceSampling::kFreeFlight, DistanceSampling::kEquiangular, DistanceSampling::kMis}) {
            PathOptions options;
            options.quad_lights = quads;
            MediumWalk walk;
            walk.distance = s;
            const Prepared p(scene, options, walk);
            REQUIRE(!p.simulated.contains(Effect::kIndirect));
            const Estimate e = estimate(p.tracer, ray, 40000, 5);
            INFO(to_string(quads) << ", " << to_string(s) << ": " << e.mean << " ± " << e.error << ", exact "
                                  << exact);
            CHECK(std::abs(e.mean - exact) < 4 * e.error);
            CHECK(e.error < 0.01 * exact);
        }
}

TEST_CASE(
    "The thin fog with --distance-sampling mis agrees with free flight, in mean and per region, with "
    "quad lights by area and by solid angle (whose equiangular target is still a point by area)",
    "[equiangular]"
    "[ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch03.shadow_"
    "ray]"
    "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06."
    "mis_weight]"
    "[ex:ch06.path_tracer][ex:ch07.beer_lambert][ex:ch09.free_flight][ex:ch09.hg_sample][ex:ch09."
    "transmittance]"
    "[ex:ch09.volume_vertex]") {
    // ch09_thin_fog.json at 40×40: the difference of two images, pixel by pixel (independent pixels), in each
    // of its four quadrants and in all, within 4 standard errors of 0.
    const Scene scene = load_scene(scene_path("ch09_thin_fog.json"));
    const EffectSet simulated = simulated_effects(scene, kMediaChapterEffects);
    const RenderSettings settings = small_render(40, 128, 3);
    MediumWalk mis;
    mis.distance = DistanceSampling::kMis;
    const RenderResult a = render_with_media(choose_renderer(simulated), scene, simulated, settings);
    for (const QuadLightSampling quads : {QuadLightSampling::kArea, QuadLightSampling::kSolidAngle}) {
        RenderSettings other = settings;
        other.seed = 4;
        PathOptions options;
        options.quad_lights = quads;
        const RenderResult b =
            render_with_media(choose_renderer(simulated), scene, simulated, other, options, mis);
        CHECK(b.rays[RayKind::kShadow] > a.rays[RayKind::kShadow]);  // the equiangular points' shadow rays
        for (int region = 0; region < 5; ++region) {
            double sum = 0, sum2 = 0;
            int n = 0;
            for (int y = 0; y < 40; ++y)
                for (int x = 0; x < 40; ++x) {
                    if (region < 4 && (x / 20 + 2 * (y / 20)) != region) continue;
                    const Color d = b.image.at(x, y) - a.image.at(x, y);
                    const double v = (double(d.r) + double(d.g) + double(d.b)) / 3;
                    sum += v;
                    sum2 += v * v;
                    ++n;
                }
            const double mean = sum / n, error = std::sqrt((sum2 / n - mean * mean) / (n - 1));
            INFO(to_string(quads) << ", region " << region << ": mis − free flight = " << mean << " ± "
                                  << error << ", image mean " << a.image.mean());
            CHECK(std::abs(mean) < 4 * error);
        }
    }
}

TEST_CASE("A chromatic medium keeps free flight under --distance-sampling mis: the same image to the bit",
          "[equiangular]"
          "[ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch03."
          "shadow_ray]"
          "[ex:ch04.cosine_hemisphere][ex:ch04.lambert][ex:ch05.termination][ex:ch06.mis_weight]"
          "[ex:ch06.path_tracer][ex:ch07.beer_lambert][ex:ch09.free_flight][ex:ch09.hg_sample][ex:ch09."
          "transmittance]"
          "[ex:ch09.volume_vertex]") {
    const Scene scene = scene_from(R"({
        "camera": {"from": [0, 0, 5], "at": [0, 0, 0]},
        "medium": {"sigma_a": [0.02, 0.05, 0.1], "sigma_s": [0.1, 0.1, 0.1]},
        "lights": [{"type": "point", "position": [0, 1, 0], "intensity": [10, 10, 10]}],
        "materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
        "shapes": [{"type": "quad", "origin": [-50, -50, -5], "u": [100, 0, 0], "v": [0, 100, 0],
                    "material": "white"}]})");
    const EffectSet simulated = simulated_effects(scene, kMediaChapterEffects);
    MediumWalk mis;
    mis.distance = DistanceSampling::kMis;
    const RenderSettings settings = small_render(12, 4, 1);
    const RenderResult a = render_with_media(choose_renderer(simulated), scene, simulated, settings);
    const RenderResult b = render_with_media(choose_renderer(simulated), scene, simulated, settings, {}, mis);
    CHECK(a.image.pixels() == b.image.pixels());
    CHECK(a.rays[RayKind::kShadow] == b.rays[RayKind::kShadow]);
}

TEST_CASE("An environment behind endless fog is named in the summary: none of its light arrives, exactly",
          "[media][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch04.sample_quad_light][ex:ch06.mis_weight]"
          "[ex:ch06.path_tracer][ex:ch06.uniform_sphere][ex:ch09.free_flight][ex:ch09.hg_sample]"
          "[ex:ch09.transmittance][ex:ch09.volume_vertex]") {
    const RenderSettings settings = small_render(8, 4, 3);
    const auto run = [&](const std::string& medium) {
        const Scene scene = parse_scene(std::string(R"({"camera": {"from": [0, 0, 0], "at": [0, 0, -1]},
            "lights": [{"type": "environment", "radiance": [1, 2, 3]}], "medium": )") +
                                            medium + "}",
                                        "fog.json");
        return render_by_choice(TracerRule::kAuto,
                                {scene, settings, simulated_effects(scene, kMediaChapterEffects)}, {}, {});
    };
    const auto note_in = [](const ChapterRun& r) {
        for (const std::string& note : r.notes) {
            if (note.rfind("environment:", 0) == 0) return note;
        }
        return std::string("no note");
    };
    // Fog whose mean free path is a million times the scene still fills all space: the exact answer is 0.
    const ChapterRun thin = run(R"({"sigma_a": [1e-7, 1e-7, 1e-7], "sigma_s": [1e-6, 1e-6, 1e-6]})");
    CHECK(note_in(thin) ==
          "environment: none of its light arrives in r, g, b: the fog (top-level medium) fills "
          "all space, and light from infinitely far is extinguished wherever sigma_a + "
          "sigma_s > 0");
    for (const Color& pixel : thin.result.image.pixels()) CHECK(pixel == Color(0));
    // A channel the fog leaves clear sees the environment whole, and the note names only the others.
    const ChapterRun green = run(R"({"sigma_a": [0.5, 0, 0.5]})");
    CHECK(note_in(green) ==
          "environment: none of its light arrives in r, b: the fog (top-level medium) fills "
          "all space, and light from infinitely far is extinguished wherever sigma_a + "
          "sigma_s > 0");
    for (const Color& pixel : green.result.image.pixels()) CHECK(pixel == Color(0, 2, 0));
    // Clear air: no note.
    CHECK(note_in(run(R"({"sigma_a": [0, 0, 0]})")) == "no note");
}
