// Chapter 10: denoising. The filters on images made for the purpose (a constant image stays, weights sum to
// 1, range parameters at 0 give the input back, a flat noisy patch loses the variance the kernel predicts,
// an albedo step stays sharp, zero variance or albedo gives no NaN, any thread count the same bits), SSIM
// (1 for identical images, symmetric), and the feature buffers the path loop records (the noisy image is
// chapter 07's to the bit; a wall's albedo, normal and depth; the depth through the glass sphere). The
// variance of a pixel's mean from exact sums is common's (tests/common_test.cpp).
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "07_bsdf_refraction/bsdf_render.hpp"
#include "10_denoising/atrous.hpp"
#include "10_denoising/bilateral.hpp"
#include "10_denoising/denoise_study.hpp"
#include "10_denoising/denoiser.hpp"
#include "10_denoising/edge_stopping.hpp"
#include "10_denoising/feature_buffers.hpp"
#include "10_denoising/path_features.hpp"
#include "10_denoising/ssim.hpp"
#include "rt/io/effects.hpp"
#include "rt/core/random.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"

using namespace rt;

namespace {

// Buffers of `width` × `height` with every guide flat (one normal, depth and albedo), the colour `colour(x,
// y)` and a colour variance `variance` per channel.
template <typename Colour>
FeatureBuffers flat_buffers(int width, int height, Colour&& colour, Real variance = Real(0.01)) {
    FeatureBuffers b;
    b.colour = b.colour_variance = b.albedo = b.albedo_variance = b.normal = b.normal_variance = b.depth =
        b.depth_variance = Image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            b.colour.at(x, y) = colour(x, y);
            b.colour_variance.at(x, y) = Color(variance);
            b.albedo.at(x, y) = Color(Real(0.5));
            b.normal.at(x, y) = Color(0, 0, 1);
            b.depth.at(x, y) = Color(10);
        }
    }
    return b;
}

// Buffers whose every guide varies from pixel to pixel (random), seeded.
FeatureBuffers random_buffers(int width, int height, std::uint64_t seed) {
    Pcg32 rng(seed, 7);
    FeatureBuffers b = flat_buffers(
        width, height, [&](int, int) { return Color(rng.next_real(), rng.next_real(), rng.next_real()); });
    for (std::size_t i = 0; i < b.colour.pixel_count(); ++i) {
        b.colour_variance.pixels()[i] = Color(rng.next_real() * Real(0.05));
        b.albedo.pixels()[i] = Color(rng.next_real(), rng.next_real(), rng.next_real());
        b.normal.pixels()[i] =
            Color(glm::normalize(Vec3(rng.next_real() - Real(0.5), rng.next_real() - Real(0.5), 1)));
        b.depth.pixels()[i] = Color(5 + rng.next_real());
    }
    return b;
}

BilateralSettings bilateral_with(const EdgeStopping& edges, Real spatial = 2) {
    BilateralSettings s;
    s.spatial = spatial;
    s.edges = edges;
    return s;
}

AtrousSettings atrous_with(const EdgeStopping& edges, int levels = 3) {
    AtrousSettings s;
    s.levels = levels;
    s.edges = edges;
    return s;
}

const EdgeStopping kAllZero{0, 0, 0, 0};
const EdgeStopping kOff{kInfinity, kInfinity, kInfinity, kInfinity};

double channel_variance(const Image& image, int x0, int y0, int x1, int y1) {
    double sum = 0, squares = 0, n = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const double v = image.at(x, y).r;
            sum += v;
            squares += v * v;
            n += 1;
        }
    }
    return (squares - sum * sum / n) / (n - 1);
}

}  // namespace

TEST_CASE("A constant image comes out of either filter unchanged, whatever the guides",
          "[filters][ex:ch10.atrous_pixel][ex:ch10.edge_stopping]") {
    FeatureBuffers b = random_buffers(40, 30, 3);
    for (Color& c : b.colour.pixels()) c = Color(Real(0.25), Real(0.5), Real(2));
    const EdgeStopping edges;
    for (const Image& out :
         {bilateral_filter(b, bilateral_with(edges), 2), atrous_filter(b, atrous_with(edges, 5), 2)}) {
        for (const Color& c : out.pixels()) {
            REQUIRE(c.r == Approx(0.25).epsilon(1e-6));
            REQUIRE(c.g == Approx(0.5).epsilon(1e-6));
            REQUIRE(c.b == Approx(2).epsilon(1e-6));
        }
    }
}

TEST_CASE("The weights of every pixel sum to 1, borders and corners included",
          "[filters][ex:ch10.atrous_pixel][ex:ch10.edge_stopping]") {
    const FeatureBuffers b = random_buffers(24, 20, 5);
    const std::vector<GuidePixel> guides = guide_pixels(b);
    const EdgeStopping edges;
    for (int y : {0, 1, 10, 19}) {
        for (int x : {0, 3, 12, 23}) {
            double bilateral = 0;
            for (Real w : bilateral_weights(guides, 24, 20, x, y, bilateral_with(edges))) bilateral += w;
            CHECK(bilateral == Approx(1).epsilon(1e-5));
            for (int step : {1, 2, 4}) {
                Real weights[25];
                atrous_pixel(guides, 24, 20, x, y, step, edges, weights);
                double atrous = 0;
                for (Real w : weights) atrous += w;
                CHECK(atrous == Approx(1).epsilon(1e-5));
            }
        }
    }
}

TEST_CASE("Range parameters at 0 give the input back, to the bit",
          "[filters][ex:ch10.atrous_pixel][ex:ch10.edge_stopping]") {
    const FeatureBuffers b = random_buffers(32, 24, 9);
    const Image bilateral = bilateral_filter(b, bilateral_with(kAllZero), 2);
    const Image atrous = atrous_filter(b, atrous_with(kAllZero, 5), 2);
    REQUIRE(bilateral.pixels() == b.colour.pixels());
    REQUIRE(atrous.pixels() == b.colour.pixels());
}

TEST_CASE("On a flat noisy patch each filter leaves the variance its fixed kernel predicts",
          "[filters][statistical][ex:ch10.atrous_pixel][ex:ch10.edge_stopping]") {
    // Uniform noise in [0, 1): variance 1/12. With every guide equal and the colour's switched off, each
    // filter is a fixed linear kernel k of independent pixels, whose output variance follows from k.
    const int size = 256;
    Pcg32 rng(11, 3);
    const FeatureBuffers b = flat_buffers(size, size, [&](int, int) { return Color(rng.next_real()); });
    const double input = 1.0 / 12;
    SECTION("bilateral: k = the normalised Gaussian of sigma_s 2 on its 9x9 window") {
        double total = 0, squares = 0;
        for (int dy = -4; dy <= 4; ++dy) {
            for (int dx = -4; dx <= 4; ++dx) {
                const double g = std::exp(-(dx * dx + dy * dy) / 8.0);
                total += g;
                squares += g * g;
            }
        }
        const double predicted = input * squares / (total * total);
        const Image out = bilateral_filter(b, bilateral_with(kOff, 2), 2);
        CHECK(channel_variance(out, 8, 8, size - 8, size - 8) == Approx(predicted).epsilon(0.08));
        // The kernel does reduce it, by about 25 times here.
        CHECK(predicted < input / 20);
    }
    SECTION("atrous: k = the B3 taps at steps 1, 2, 4 convolved, in each axis") {
        std::vector<double> kernel{1};
        for (int step : {1, 2, 4}) {
            std::vector<double> next(kernel.size() + std::size_t(4 * step), 0);
            for (std::size_t i = 0; i < kernel.size(); ++i)
                for (std::size_t t = 0; t < 5; ++t) next[i + t * std::size_t(step)] += kernel[i] * kB3Taps[t];
            kernel = next;
        }
        double squares = 0;
        for (double k : kernel) squares += k * k;
        const double predicted = input * squares * squares;  // separable: (Σ k_1d²)²
        const Image out = atrous_filter(b, atrous_with(kOff, 3), 2);
        CHECK(channel_variance(out, 16, 16, size - 16, size - 16) == Approx(predicted).epsilon(0.08));
        CHECK(predicted < input / 20);
    }
}

TEST_CASE("A step edge in the albedo guide stays sharp",
          "[filters][ex:ch10.atrous_pixel][ex:ch10.edge_stopping]") {
    // Left half 0.2, right half 0.8, plus noise; the albedo guide steps at the same column. With the colour
    // guide off, only the albedo keeps the halves apart.
    const int w = 64, h = 48;
    Pcg32 rng(13, 1);
    FeatureBuffers b = flat_buffers(w, h, [&](int x, int) {
        return Color((x < w / 2 ? Real(0.2) : Real(0.8)) + Real(0.1) * (rng.next_real() - Real(0.5)));
    });
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) b.albedo.at(x, y) = Color(x < w / 2 ? Real(0.2) : Real(0.8));
    EdgeStopping guided = kOff;
    guided.albedo = Real(0.1);
    auto column_mean = [&](const Image& image, int x) {
        double sum = 0;
        for (int y = 0; y < h; ++y) sum += image.at(x, y).r;
        return sum / h;
    };
    const int left = w / 2 - 1, right = w / 2;
    for (bool atrous : {false, true}) {
        const Image sharp = atrous ? atrous_filter(b, atrous_with(guided), 2)
                                   : bilateral_filter(b, bilateral_with(guided), 2);
        const Image blurred =
            atrous ? atrous_filter(b, atrous_with(kOff), 2) : bilateral_filter(b, bilateral_with(kOff), 2);
        CHECK(column_mean(sharp, left) == Approx(0.2).margin(0.01));
        CHECK(column_mean(sharp, right) == Approx(0.8).margin(0.01));
        // Without the guide the edge columns mix toward 0.5.
        CHECK(column_mean(blurred, left) > 0.35);
        CHECK(column_mean(blurred, right) < 0.65);
    }
}

TEST_CASE("Zero variance, zero albedo, zero normal and zero depth give no NaN",
          "[filters][ex:ch10.atrous_pixel][ex:ch10.edge_stopping]") {
    Pcg32 rng(17, 2);
    FeatureBuffers b = flat_buffers(
        20, 16, [&](int, int) { return Color(rng.next_real() * 4); }, 0);
    for (std::size_t i = 0; i < b.colour.pixel_count(); ++i) {
        b.albedo.pixels()[i] = Color(0);
        b.normal.pixels()[i] = Color(0);
        b.depth.pixels()[i] = Color(i % 2 == 0 ? 0 : 3);
    }
    for (const EdgeStopping& edges : {EdgeStopping{}, kAllZero, kOff}) {
        REQUIRE(bilateral_filter(b, bilateral_with(edges), 1).all_finite());
        REQUIRE(atrous_filter(b, atrous_with(edges, 5), 1).all_finite());
    }
    const GuidePixel zero;
    GuidePixel other;
    other.colour = Color(1);
    for (const EdgeStopping& edges : {EdgeStopping{}, kAllZero, kOff}) {
        CHECK(edge_stopping_weight(zero, zero, edges) == 1);
        const Real w = edge_stopping_weight(zero, other, edges);
        CHECK(std::isfinite(w));
        CHECK(w >= 0);
    }
}

TEST_CASE("Either filter gives the same bits on 1, 2 and 5 threads",
          "[filters][ex:ch10.atrous_pixel][ex:ch10.edge_stopping]") {
    const FeatureBuffers b = random_buffers(37, 29, 21);
    const EdgeStopping edges;
    const Image bilateral = bilateral_filter(b, bilateral_with(edges), 1);
    const Image atrous = atrous_filter(b, atrous_with(edges, 5), 1);
    for (int threads : {2, 5}) {
        CHECK(bilateral_filter(b, bilateral_with(edges), threads).pixels() == bilateral.pixels());
        CHECK(atrous_filter(b, atrous_with(edges, 5), threads).pixels() == atrous.pixels());
    }
}

TEST_CASE("SSIM: identical images give 1, it is symmetric, and noise lowers it", "[ssim]") {
    const FeatureBuffers a = random_buffers(30, 20, 1), b = random_buffers(30, 20, 2);
    REQUIRE(ssim(a.colour, a.colour) == 1.0);
    REQUIRE(ssim(a.colour, b.colour) == ssim(b.colour, a.colour));
    Image noisy = a.colour;
    Pcg32 rng(5, 5);
    for (Color& c : noisy.pixels()) c += Color(Real(0.1) * (rng.next_real() - Real(0.5)));
    const double s = ssim(a.colour, noisy);
    CHECK(s < 0.99);
    CHECK(s > ssim(a.colour, b.colour));
    CHECK_THROWS(ssim(a.colour, Image(20, 30)));
}

TEST_CASE("Recording the features changes nothing: the noisy image is chapter 07's to the bit",
          "[features][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]"
          "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    const Scene scene = load_scene(scene_path("cornell.json"));
    RenderSettings s;
    s.width = 40, s.height = 40, s.samples_per_pixel = 3, s.seed = 4, s.threads = 2,
    s.progress = ProgressStyle::kNone;
    PathOptions options;
    options.simulated = needed(scene);
    const FeatureRender features = render_features(scene, s, options);
    const RenderResult plain = render_with(Renderer::kPaths, scene, options.simulated, s, options);
    REQUIRE(features.buffers.colour.pixels() == plain.image.pixels());
    REQUIRE(features.result.rays.total() == plain.rays.total());
}

TEST_CASE("The normal feature is the shading normal: a smooth mesh's, not its facet's", "[features]") {
    Hit hit;
    hit.t = 2;
    hit.normal = Vec3(0, 0, 1);
    hit.shading_normal = glm::normalize(Vec3(0.3f, -0.2f, 1));
    PathFeatures features;
    REQUIRE(features.reached(hit, BsdfFlags{}, 0));
    CHECK(features.normal == hit.shading_normal);
    CHECK(features.depth == 2);
}

TEST_CASE("The features of the back wall and of the glass sphere",
          "[features][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.lambert]"
          "[ex:ch04.sample_quad_light][ex:ch05.termination][ex:ch06.mis_weight][ex:ch06.path_tracer]"
          "[ex:ch07.dielectric_sample][ex:ch07.fresnel_exact][ex:ch07.refract]") {
    // cornell.json, 61x61: pixel (30, 20) sees the back wall (white, 0.73) over the tall box, at (278, 440,
    // 555), 1364.6 from the eye; a pixel on the glass sphere sees through it to what lies behind, farther
    // than the sphere's front.
    const Scene scene = load_scene(scene_path("cornell.json"));
    RenderSettings s;
    s.width = 61, s.height = 61, s.samples_per_pixel = 16, s.seed = 1, s.threads = 2,
    s.progress = ProgressStyle::kNone;
    PathOptions options;
    options.simulated = needed(scene);
    const FeatureBuffers b = render_features(scene, s, options).buffers;
    // Lambert sampled by the cosine: f cos / pdf is the albedo in every sample.
    CHECK(b.albedo.at(30, 20).r == Approx(0.73).epsilon(1e-4));
    CHECK(b.albedo_variance.at(30, 20).r == Approx(0).margin(1e-9));
    CHECK(b.normal.at(30, 20).b == Approx(-1).epsilon(1e-5));
    CHECK(b.depth.at(30, 20).r == Approx(1364.6).epsilon(2e-3));
    // The sphere (centre (190, 90, 190), radius 90) is at pixel (38, 46), its centre 1009 from the eye:
    // through it, along the line from the eye, lies the back wall, 1371 away; the ray leaves the glass nearly
    // undeviated there, so the features are mostly the wall's (the 4 % reflected off the front are not).
    CHECK(b.depth.at(38, 46).r > 1200);
    CHECK(b.normal.at(38, 46).b < -0.8);
    CHECK(b.albedo.at(38, 46).r < 0.73);  // the wall's albedo, less what the glass reflects away
}

TEST_CASE("The edge-stopping weight is exp(-sum of d2 / s2) on guides worked by hand, each guide alone too",
          "[filters][ex:ch10.edge_stopping]") {
    GuidePixel p, q;
    p.colour = Color(Real(0.5));
    q.colour = Color(Real(0.8), Real(0.5), Real(0.9));  // d² = 0.09 + 0.16 = 0.25
    p.variance = Real(0.05), q.variance = Real(0.075);  // s² = 2² (0.05 + 0.075) = 0.5: the term 0.5
    p.normal = Vec3(0, 0, 1), q.normal = Vec3(Real(0.6), 0, Real(0.8));  // d² = 0.36 + 0.04 = 0.4, s² = 1
    p.depth = 4, q.depth = 5;  // d² = 1, s² = (0.2 · max(4, 5))² = 1
    p.albedo = Color(Real(0.5)), q.albedo = Color(Real(0.5), Real(0.8), Real(0.5));  // d² = 0.09 = s²
    EdgeStopping colour = kOff, normal = kOff, depth = kOff, albedo = kOff;
    colour.colour = 2, normal.normal = 1, depth.depth = Real(0.2), albedo.albedo = Real(0.3);
    for (const bool swapped : {false, true}) {  // w(p, q) = w(q, p)
        const GuidePixel& a = swapped ? q : p;
        const GuidePixel& b = swapped ? p : q;
        CHECK(edge_stopping_weight(a, b, colour) == Approx(std::exp(-0.5)).epsilon(1e-5));
        CHECK(edge_stopping_weight(a, b, normal) == Approx(std::exp(-0.4)).epsilon(1e-5));
        CHECK(edge_stopping_weight(a, b, depth) == Approx(std::exp(-1.0)).epsilon(1e-5));
        CHECK(edge_stopping_weight(a, b, albedo) == Approx(std::exp(-1.0)).epsilon(1e-5));
        CHECK(edge_stopping_weight(a, b, EdgeStopping{}) == Approx(std::exp(-2.9)).epsilon(1e-5));
        CHECK(edge_stopping_weight(a, b, kOff) == 1);
    }
}

TEST_CASE("One a-trous level gives the variance of its weighted mean, inside and at a corner",
          "[filters][ex:ch10.atrous_pixel][ex:ch10.edge_stopping]") {
    // Every guide equal and the colour's off: w = h = h_j h_k, a weighted mean of independent pixels. Inside,
    // Σ h_j = 1 and Σ h_j² = 70/256 in each axis; at the corner (0, 0) only taps 0, step, 2 step of each axis
    // are in the image, weighing 6, 4, 1 (/16): Σ h_j² / (Σ h_j)² = (53/256) / (11/16)². The colour x + 2y is
    // linear: inside it stays, at the corner it is the weighted mean, 6 step/11 in x and in y.
    const int size = 20;
    const FeatureBuffers b = flat_buffers(size, size, [](int x, int y) { return Color(Real(x + 2 * y)); });
    const std::vector<GuidePixel> guides = guide_pixels(b);  // variance 0.03: three channels of 0.01
    const double v = 0.03, inside = 70.0 / 256, corner = (53.0 / 256) / ((11.0 / 16) * (11.0 / 16));
    for (const int step : {1, 2, 4}) {
        INFO("step " << step);
        const GuidePixel middle = atrous_pixel(guides, size, size, 10, 9, step, kOff);
        const GuidePixel edge = atrous_pixel(guides, size, size, 0, 0, step, kOff);
        {
            INFO("the output's variance is not that of a normalised weighted mean of independent pixels");
            CHECK(middle.variance == Approx(v * inside * inside).epsilon(1e-5));
            CHECK(edge.variance == Approx(v * corner * corner).epsilon(1e-5));
        }
        INFO("the filtered colour is not the normalised weighted mean of its taps");
        CHECK(middle.colour.r == Approx(28).epsilon(1e-5));
        CHECK(edge.colour.r == Approx(3 * 6.0 * step / 11).epsilon(1e-5));
    }
}
