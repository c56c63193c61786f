// What chapter 07 costs, measured (not a test): `ch07_benchmark` prints the tables of the lesson.
//  1. samples (paths) per second on the glass Cornell box (cornell.json, 600×600): the median of --repeats;
//  2. only the effects a scene calls for: chapter 07 against chapter 04 on the box called for shadows and
//     direct light only, and against chapter 06 on the box without glass (ch06_default.json); the renders
//     alternate, so both see the same load, and the ratio of the medians is reported;
//  3. the time to a relative MSE of --target on --conv-scene against a converged reference (two halves A and
//     B, cached as PFM; its own noise mean((A − B)² / (r² + 0.01)) / 4 is subtracted), for chapter 06's loop
//     with MIS (this chapter's renderer), with next-event estimation alone ("light", what this chapter did
//     before it rendered through chapter 06's loop) and without light sampling ("brdf"), each at growing spp
//     until it is within 4× of the target, extrapolated with relMSE ∝ 1 / spp.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "04_direct_lighting/direct_render.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "bsdf_render.hpp"
#include "reference_halves.hpp"
#include "rt/core/median.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/run/strict_flags.hpp"

namespace {

using namespace rt;

RenderResult chapter07(const Scene& scene, const RenderSettings& settings, PathOptions options = {}) {
    const EffectSet simulated = needed(scene) & EffectSet::all();
    return render_with(choose_renderer(simulated), scene, simulated, settings, options);
}

// The relative MSE of `image` against r = (A + B) / 2: mean((x − r)² / (r² + 0.01)).
double relative_mse(const Image& image, const Image& a, const Image& b) {
    double sum = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const Color r = (a.at(x, y) + b.at(x, y)) * Real(0.5);
            const Color d = image.at(x, y) - r;
            for (int c = 0; c < 3; ++c) sum += double(d[c] * d[c]) / (double(r[c] * r[c]) + 0.01);
        }
    }
    return sum / (3.0 * double(image.width()) * double(image.height()));
}

void run(int size, int spp, int repeats, int threads, int conv_size, int reference_spp, int max_spp,
         double target, const std::string& cache, bool speed_only, const std::string& conv_scene);

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("ch07_benchmark: glass path tracer speed, effects cost and time to a relative MSE",
                 "ch07_benchmark");
    app.option_defaults()->always_capture_default();  // --help shows each flag's default
    int size = 600, spp = 8, repeats = 3, threads = 2, conv_size = 150, reference_spp = 4096, max_spp = 2048;
    double target = 1e-3;
    std::string cache = ".";
    std::string conv_scene = "cornell.json";
    app.add_option("--size", size, "Width and height of the timed renders")->check(CLI::Range(8, 4096));
    app.add_option("--spp", spp, "Samples per pixel of each timed render")->check(CLI::Range(1, 1 << 16));
    app.add_option("--repeats", repeats, "Timed renders per row (the median is reported)")
        ->check(CLI::Range(1, 100));
    app.add_option("--threads", threads, "Render threads")->check(CLI::Range(1, 1024));
    app.add_option("--conv-size", conv_size, "Width and height for the time to --target")
        ->check(CLI::Range(8, 4096));
    app.add_option("--reference-spp", reference_spp, "Samples per pixel of the reference (two halves)")
        ->check(CLI::Range(2, 1 << 20));
    app.add_option("--max-spp", max_spp, "The largest spp tried for the time to --target")
        ->check(CLI::Range(1, 1 << 20));
    app.add_option("--target", target, "The relative MSE to reach")->check(CLI::Range(1e-8, 1.0));
    app.add_option("--conv-scene", conv_scene,
                   "Scene of the time to --target (default cornell.json; ch07_glossy_glass.json for MIS)");
    app.add_option("--cache", cache, "Folder of the cached reference PFMs")->check(CLI::ExistingDirectory);
    bool speed_only = false;
    app.add_flag("--speed-only", speed_only, "Only the samples per second");
    if (const auto stop = rt::read_flags(app, argc, argv)) return *stop;
    try {
        run(size, spp, repeats, threads, conv_size, reference_spp, max_spp, target, cache, speed_only, conv_scene);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ch07_benchmark: %s\n", e.what());
        return 1;
    }
    return 0;
}

namespace {

// 1. Samples per second on the glass Cornell box.
void measure_speed(const Scene& cornell, const RenderSettings& settings, int repeats) {
    // Processor time (every thread of this process) as well as wall-clock time: on a shared machine the
    // samples per processor-second times the thread count is what the threads would give with the cores to
    // themselves.
    std::vector<double> rates, cpu_rates;
    for (int r = 0; r < repeats; ++r) {
        const std::clock_t start = std::clock();
        const RenderResult result = chapter07(cornell, settings);
        const double cpu = double(std::clock() - start) / CLOCKS_PER_SEC;
        rates.push_back(double(result.samples) / result.seconds);
        cpu_rates.push_back(double(result.samples) / cpu);
    }
    std::printf(
        "glass Cornell box (cornell.json): %.3g samples/s (median; min %.3g, max %.3g); %.3g samples "
        "per processor-second, x %d threads = %.3g\n",
        median(rates), *std::min_element(rates.begin(), rates.end()),
        *std::max_element(rates.begin(), rates.end()), median(cpu_rates), settings.threads,
        median(cpu_rates) * settings.threads);
}

// 2. Only the effects a scene calls for: chapter 07 against chapter 04, and against chapter 06.
void measure_effects_cost(const Scene& cornell, const RenderSettings& settings, int repeats) {
    const int size = settings.width;
    Scene direct_only = cornell;
    direct_only.effects = EffectSet{Effect::kShadows, Effect::kDirect};
    const Scene no_glass = load_scene(scene_path("ch06_default.json"));
    struct Pair {
        const char* name;
        const Scene& scene;
        bool against_04;
    };
    for (const Pair& p : {Pair{"box, effects shadows+direct: ch07 / ch04", direct_only, true},
                          Pair{"box without glass (ch06_default): ch07 / ch06", no_glass, false}}) {
        const EffectSet simulated = needed(p.scene) & EffectSet::all();
        const RenderScene prepared(p.scene, simulated);
        const PinholeCamera camera = make_pinhole_camera(p.scene.camera, size, size);
        std::vector<double> ours, theirs;
        for (int r = 0; r < repeats; ++r) {
            ours.push_back(chapter07(p.scene, settings).seconds);
            if (p.against_04) {
                DirectOptions direct;
                direct.simulated = simulated;
                const DirectLighting shading(prepared.world, prepared.materials, prepared.lights, direct);
                theirs.push_back(render_direct(shading, camera, settings, FilmPoints::kStratified).seconds);
            } else {
                PathOptions paths;
                paths.simulated = simulated;
                const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, paths);
                theirs.push_back(render_paths(tracer, camera, settings).seconds);
            }
        }
        std::printf("%-48s %8.3f s / %8.3f s = %.3f  (renderer: %s)\n", p.name, median(ours), median(theirs),
                    median(ours) / median(theirs),
                    std::string(to_string(choose_renderer(simulated))).c_str());
    }
}

// 3. Time to the target relative MSE, for each sampling strategy.
void measure_time_to_target(const RenderSettings& settings, int conv_size, int reference_spp, int max_spp,
                            double target, const std::string& cache, const std::string& conv_scene) {
    const Scene converging = load_scene(scene_path(conv_scene.c_str()));
    RenderSettings conv = settings;
    conv.width = conv.height = conv_size;
    const std::string stem = "ch07_benchmark_reference_" + std::filesystem::path(conv_scene).stem().string() +
                             "_" + std::to_string(conv_size) + "_" + std::to_string(reference_spp) + "spp";
    // Chapter 07's own renderer for the scene, as chapter07() chooses it.
    const Renderer renderer = choose_renderer(needed(converging) & EffectSet::all());
    const std::filesystem::path halves = std::filesystem::path(cache) / stem;
    const Image a = cached_half(renderer, converging, conv, reference_spp / 2, 1001, halves.string() + "_a.pfm");
    const Image b = cached_half(renderer, converging, conv, reference_spp / 2, 1002, halves.string() + "_b.pfm");
    const double noise = relative_mse(a, a, b) / 4;  // (A − r) = (A − B) / 2; the mean's noise is a quarter
    std::printf(
        "\ntime to relative MSE %.0e, %s %dx%d, reference %d spp (its own relative MSE %.2e)\n", target,
        conv_scene.c_str(), conv_size, conv_size, reference_spp, noise);
    std::printf("%-22s %6s %12s %10s %16s\n", "estimator", "spp", "rel. MSE", "time (s)", "time to target");
    for (SamplingStrategy strategy :
         {SamplingStrategy::kMis, SamplingStrategy::kLight, SamplingStrategy::kBrdf}) {
        PathOptions options;
        options.strategy = strategy;
        double estimate = 0;
        for (int n = 1; n <= max_spp; n *= 2) {
            conv.samples_per_pixel = n;
            conv.seed = 7;
            const RenderResult r = chapter07(converging, conv, options);
            const double rel = std::max(0.0, relative_mse(r.image, a, b) - noise);
            estimate = r.seconds * rel / target;
            std::printf("%-22s %6d %12.4e %10.3f %14.3f s\n", to_string(strategy).data(), n, rel, r.seconds,
                        estimate);
            if (rel < 4 * target) break;
        }
    }
}

void run(int size, int spp, int repeats, int threads, int conv_size, int reference_spp, int max_spp,
         double target, const std::string& cache, bool speed_only, const std::string& conv_scene) {
    const Scene cornell = load_scene(scene_path("cornell.json"));
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.samples_per_pixel = spp;
    settings.seed = 1;
    settings.threads = threads;
    settings.progress = ProgressStyle::kNone;
    std::printf("ch07_benchmark: %dx%d, %d spp, %d threads, median of %d\n", size, size, spp, threads,
                repeats);
    measure_speed(cornell, settings, repeats);
    if (speed_only) return;
    measure_effects_cost(cornell, settings, repeats);
    measure_time_to_target(settings, conv_size, reference_spp, max_spp, target, cache, conv_scene);
}

}  // namespace
