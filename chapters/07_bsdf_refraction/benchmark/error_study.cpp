// Where the error of a scene comes from, measured (not a test): `ch07_error_study` prints the tables of
// chapter 06's lesson on it, for the glass Cornell box (cornell.json) or the scene --scene names.
//  1. One render of --spp samples against a converged reference r = (A + B) / 2 (two halves, cached as PFM;
//     its own noise mean((A − r)² / (r² + 0.01)) is subtracted): its relative MSE, the share of its squared
//     error in the worst 1 % of pixels, its median pixel's error, and an error picture (--error-png).
//  2. The same render's estimate split by the kind of path each term came from (path_parts.hpp: seen, next
//     event, BSDF hit, caustic), and by its length (bounces), each part's share of the image and of the
//     estimator's variance, Σ Var[part] / (r² + 0.01) over every pixel and channel (the covariances between
//     the parts are the rest), over all pixels and over the worst 1 %.
//  3. The candidate causes, each a variant of the path loop's options, rendered in turn (alternating, the
//     mean relative MSE and median seconds of --repeats, each with its own seed) at --spp, and the time to a
//     relative MSE of --target, extrapolated with relMSE ∝ 1 / time.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "01_ray_generation/camera_render.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "06_monte_carlo/render_paths.hpp"
#include "bsdf_render.hpp"
#include "path_parts.hpp"
#include "reference_halves.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/core/median.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/false_colour.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/run/strict_flags.hpp"

namespace {

using namespace rt;

// Each pixel's squared error over its channels, relative: Σ_c (x − r)² / (r² + 0.01).
std::vector<double> pixel_errors(const Image& image, const Image& r) {
    std::vector<double> e;
    e.reserve(std::size_t(image.width() * image.height()));
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const Color d = image.at(x, y) - r.at(x, y);
            double sum = 0;
            for (int c = 0; c < 3; ++c)
                sum += double(d[c] * d[c]) / (double(r.at(x, y)[c] * r.at(x, y)[c]) + 0.01);
            e.push_back(sum);
        }
    }
    return e;
}

// The pixels (indices) holding the largest 1 % of `errors`.
std::vector<std::size_t> worst_percent(const std::vector<double>& errors) {
    std::vector<std::size_t> order(errors.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    const std::size_t n = std::max<std::size_t>(1, errors.size() / 100);
    std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(n), order.end(),
                      [&](std::size_t a, std::size_t b) { return errors[a] > errors[b]; });
    order.resize(n);
    return order;
}

// Σ_c v / (r² + 0.01) at pixel i.
double relative(const Image& v, const Image& r, std::size_t i) {
    const int x = int(i % std::size_t(v.width())), y = int(i / std::size_t(v.width()));
    double sum = 0;
    for (int c = 0; c < 3; ++c) sum += double(v.at(x, y)[c]) / (double(r.at(x, y)[c] * r.at(x, y)[c]) + 0.01);
    return sum;
}

struct Variant {
    std::string name;
    PathOptions options;
};

void run(const std::string& scene_name, int size, int spp, int reference_spp, int threads, int repeats,
         double target, const std::string& cache, const std::string& error_png);

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("ch07_error_study: where the error of a scene comes from", "ch07_error_study");
    app.option_defaults()->always_capture_default();
    int size = 150, spp = 256, reference_spp = 8192, threads = 2, repeats = 3;
    double target = 1e-3;
    std::string scene = "cornell.json", cache = ".", error_png;
    app.add_option("--scene", scene, "The scene, a file of assets/scenes");
    app.add_option("--size", size, "Width and height of the renders")->check(CLI::Range(8, 4096));
    app.add_option("--spp", spp, "Samples per pixel of the measured renders")->check(CLI::Range(2, 1 << 16));
    app.add_option("--reference-spp", reference_spp, "Samples per pixel of the reference (two halves)")
        ->check(CLI::Range(2, 1 << 20));
    app.add_option("--threads", threads, "Render threads")->check(CLI::Range(1, 1024));
    app.add_option("--repeats", repeats, "Renders of each variant (the median is reported)")
        ->check(CLI::Range(1, 100));
    app.add_option("--target", target, "The relative MSE to reach")->check(CLI::Range(1e-8, 1.0));
    app.add_option("--cache", cache, "Folder of the cached reference PFMs")->check(CLI::ExistingDirectory);
    app.add_option("--error-png", error_png,
                   "Write the per-pixel relative squared error (false colour, log10 from 1e-5 to 10) there");
    if (const auto stop = rt::read_flags(app, argc, argv)) return *stop;
    try {
        run(scene, size, spp, reference_spp, threads, repeats, target, cache, error_png);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ch07_error_study: %s\n", e.what());
        return 1;
    }
    return 0;
}

namespace {

// Sections 1 and 2: one render of `spp` with `options`, its error and its estimate split by path kind.
void split_by_path_kind(const RenderScene& prepared, const PinholeCamera& camera, const PathOptions& options,
                        RenderSettings settings, int spp, const Image& r, double noise,
                        const std::string& error_png) {
    const int size = settings.width;
    const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
    settings.samples_per_pixel = spp;
    settings.seed = 7;
    // Layers beside the image: L², then each part (the kinds, then the lengths) and its square.
    constexpr std::size_t kParts = kPathPartCount + kPathLengthCount;
    std::array<PixelSums, 1 + 2 * kParts> layers;
    const RenderResult split =
        render_layers(settings, layers, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
            PathParts parts;
            const Color L = sample_radiance(tracer, camera, settings, s, rng, rays, &parts);
            // A path whose estimate was not finite counts as black (sample_radiance): so do its parts.
            Color estimate(0);
            for (const Color& p : parts.parts) estimate += p;
            const bool dropped = !is_finite(estimate);
            std::array<Color, 2 + 2 * kParts> out;
            out[0] = L;
            out[1] = L * L;
            for (std::size_t k = 0; k < kParts; ++k) {
                const Color p = dropped              ? Color(0)
                                : k < kPathPartCount ? parts.parts[k]
                                                     : parts.lengths[k - kPathPartCount];
                out[2 + 2 * k] = p;
                out[3 + 2 * k] = p * p;
            }
            return out;
        });
    const std::vector<double> errors = pixel_errors(split.image, r);
    const std::vector<std::size_t> worst = worst_percent(errors);
    const double total = std::accumulate(errors.begin(), errors.end(), 0.0);
    double in_worst = 0;
    for (std::size_t i : worst) in_worst += errors[i];
    std::vector<double> sorted = errors;
    std::sort(sorted.begin(), sorted.end());
    std::printf(
        "\nrelative MSE %.4e (reference noise subtracted), %.1f s; worst 1 %% of pixels hold %.1f %% of the "
        "squared error; median pixel %.3e\n",
        total / double(3 * errors.size()) - noise, split.seconds, 100 * in_worst / total,
        sorted[sorted.size() / 2] / 3);
    if (!error_png.empty()) {
        // log10 of the relative squared error from 1e-5 (black) to 1e1 (white).
        Image picture(size, size);
        for (std::size_t i = 0; i < errors.size(); ++i) {
            const double t = (std::log10(std::max(errors[i] / 3, 1e-5)) + 5) / 6;
            picture.at(int(i % std::size_t(size)), int(i / std::size_t(size))) =
                linear_of_display(false_colour(t));
        }
        write_png(picture, error_png);
    }

    const Image variance = variance_image(split.sums, layers[0]);
    double v_all = 0, v_worst = 0;
    for (std::size_t i = 0; i < errors.size(); ++i) v_all += relative(variance, r, i);
    for (std::size_t i : worst) v_worst += relative(variance, r, i);
    double mean_all = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) mean_all += double(luminance(split.image.at(x, y)));
    // One row per part: its share of the image, of the variance, of the variance in the worst 1 %.
    const auto row = [&](const std::string& name, std::size_t k) {
        const Image part = layers[1 + 2 * k].mean_image();
        const Image part_variance = variance_image(layers[1 + 2 * k], layers[2 + 2 * k]);
        double mean = 0, v = 0, vw = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) mean += double(luminance(part.at(x, y)));
        for (std::size_t i = 0; i < errors.size(); ++i) v += relative(part_variance, r, i);
        for (std::size_t i : worst) vw += relative(part_variance, r, i);
        std::printf("%-12s %11.1f %% %15.1f %% %15.1f %%\n", name.c_str(), 100 * mean / mean_all,
                    100 * v / v_all, 100 * vw / v_worst);
    };
    std::printf("%-12s %12s %16s %16s\n", "path kind", "of image", "of variance", "of variance in worst 1 %");
    for (std::size_t k = 0; k < kPathPartCount; ++k) row(std::string(to_string(PathPart(k))), k);
    std::printf("%-12s %12s %16s %16s\n", "bounces", "of image", "of variance", "of variance in worst 1 %");
    for (std::size_t k = 0; k < kPathLengthCount; ++k)
        row(std::to_string(k) + (k + 1 == kPathLengthCount ? " or more" : ""), kPathPartCount + k);
}

void run(const std::string& scene_name, int size, int spp, int reference_spp, int threads, int repeats,
         double target, const std::string& cache, const std::string& error_png) {
    SceneBenchmark box(size, threads, reference_spp, cache, scene_name);
    const Scene& scene = box.scene;
    const EffectSet simulated = box.simulated;
    RenderSettings& settings = box.settings;
    const Image& r = box.reference.image;
    const double noise = box.reference.noise;  // A − r = (A − B) / 2: the mean's own noise
    std::printf("ch07_error_study: %s %dx%d, %d spp, %d threads; reference %d spp (its relative MSE %.2e)\n",
                scene_name.c_str(), size, size, spp, threads, reference_spp, noise);

    // 1 and 2: one render, its estimate split by path kind.
    const RenderScene prepared(scene, simulated, refraction_materials());
    const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
    PathOptions options;
    options.simulated = simulated;
    split_by_path_kind(prepared, camera, options, settings, spp, r, noise, error_png);

    // 3. The candidate causes.
    settings.samples_per_pixel = spp;
    std::vector<Variant> variants;
    variants.push_back({"default (sampler sobol)", options});
    for (int start : {1, 3, 5}) {
        Variant v{"roulette from bounce " + std::to_string(start), options};
        v.options.termination.roulette_start_depth = start;
        variants.push_back(v);
    }
    // Every sampler but the default (Sobol).
    for (PointSet points : {PointSet::kIndependent, PointSet::kStratified}) {
        Variant v{points == PointSet::kStratified ? "sampler stratified" : "sampler independent", options};
        v.options.sampler = points;
        variants.push_back(v);
    }
    std::printf("\n%-28s %12s %10s %16s\n", "variant", "rel. MSE", "time (s)", "time to target");
    std::vector<std::vector<double>> seconds(variants.size()), rel(variants.size());
    for (int rep = 0; rep < repeats; ++rep) {
        for (std::size_t v = 0; v < variants.size(); ++v) {
            settings.seed = std::uint64_t(7 + rep);
            const RenderResult result =
                render_with(Renderer::kPaths, scene, simulated, settings, variants[v].options);
            seconds[v].push_back(result.seconds);
            rel[v].push_back(std::max(0.0, compare(result.image, r).relative_mse - noise));
        }
    }
    for (std::size_t v = 0; v < variants.size(); ++v) {
        const double t = median(seconds[v]);
        const double e = std::accumulate(rel[v].begin(), rel[v].end(), 0.0) / double(rel[v].size());
        std::printf("%-28s %12.4e %10.3f %14.3g s\n", variants[v].name.c_str(), e, t, t * e / target);
    }
}

}  // namespace
