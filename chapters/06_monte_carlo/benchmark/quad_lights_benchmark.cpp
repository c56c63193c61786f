// Quad lights by area or by solid angle, measured (not a test). `ch06_quad_lights` prints:
//  1. what one sample costs: sample_quad_light from points around a lamp, each strategy in turn (alternating,
//     the median of --repeats), nanoseconds per sample on one thread;
//  2. for each --scene, chapter 06's path tracer (MIS) with --quad-lights area and solid-angle rendered in
//     turn, --repeats times each with its own seed, against a converged reference (chapter 06's, cached as
//     PFM in --cache): the mean relative MSE at --spp, the median seconds, and the time to a relative MSE of
//     --target, extrapolated with relMSE ∝ 1 / time.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "04_direct_lighting/quad_light_strategy.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "06_monte_carlo/convergence.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "06_monte_carlo/render_paths.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/core/errors.hpp"
#include "rt/core/median.hpp"
#include "rt/core/random.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/run/strict_flags.hpp"

namespace {

using namespace rt;

constexpr QuadLightSampling kStrategies[] = {QuadLightSampling::kArea, QuadLightSampling::kSolidAngle};

// Nanoseconds per sample of `strategy`: `count` samples of cornell.json's lamp from points spread over the
// box below it (the same points for both).
double nanoseconds_per_sample(QuadLightSampling strategy, int count) {
    const QuadLight lamp = make_quad_light({213, 554, 227}, {130, 0, 0}, {0, 0, 105}, Color(15));
    Pcg32 rng(5, 0);
    double sink = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count; ++i) {
        const Vec3 p(555 * rng.next_real(), 550 * rng.next_real(), 555 * rng.next_real());
        if (const auto s = sample_quad_light(lamp, p, rng.next_vec2(), strategy)) sink += double(s->pdf);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (sink < 0) std::printf("%g\n", sink);  // keeps the loop
    return 1e9 * seconds / count;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("ch06_quad_lights: quad lights by area or by solid angle, cost per sample and time to error",
                 "ch06_quad_lights");
    app.option_defaults()->always_capture_default();
    std::vector<std::string> scenes{scene_path("cornell.json").string(),
                                    scene_path("ch04_close_lamp.json").string()};
    int size = 128, spp = 16, repeats = 3, reference_spp = 4096, threads = 2, cost_samples = 2000000;
    std::string cache = ".";
    double target = 1e-3;
    app.add_option("--scene", scenes, "Scenes (default: cornell.json and ch04_close_lamp.json)");
    app.add_option("--size", size, "Image width and height")->check(CLI::Range(8, 4096));
    app.add_option("--spp", spp, "Samples per pixel of each measured render")->check(CLI::Range(1, 1 << 16));
    app.add_option("--repeats", repeats, "Renders (and cost runs) of each strategy")
        ->check(CLI::Range(1, 100));
    app.add_option("--reference-spp", reference_spp, "Samples per pixel of the reference")
        ->check(CLI::Range(2, 1 << 20));
    app.add_option("--threads", threads, "Render threads")->check(CLI::Range(1, 1024));
    app.add_option("--cost-samples", cost_samples, "Samples per cost run")->check(CLI::Range(1, 1 << 30));
    app.add_option("--cache", cache, "Folder of the cached reference PFMs");
    app.add_option("--target", target, "The relative MSE to reach")->check(CLI::Range(1e-8, 1.0));
    if (const auto stop = rt::read_flags(app, argc, argv)) return *stop;
    try {
        std::vector<double> ns[2];
        for (int r = 0; r < repeats; ++r)
            for (int k = 0; k < 2; ++k) ns[k].push_back(nanoseconds_per_sample(kStrategies[k], cost_samples));
        std::printf(
            "cost per sample (cornell.json's lamp, median of %d runs of %d): area %.1f ns, solid angle "
            "%.1f ns (%.2fx)\n",
            repeats, cost_samples, median(ns[0]), median(ns[1]), median(ns[1]) / median(ns[0]));
        std::printf(
            "\n| scene | quad lights | relative MSE at %d spp | seconds | time to relative MSE %.0e |\n"
            "|---|---|---|---|---|\n",
            spp, target);
        for (const std::string& file : scenes) {
            const Scene scene = load_scene(scene_path(file.c_str()));
            const RenderScene prepared(scene, EffectSet::all());
            const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
            RenderSettings settings;
            settings.width = settings.height = size;
            settings.threads = threads;
            settings.progress = ProgressStyle::kNone;
            PathOptions options;  // MIS
            const Reference ref =
                converged_reference(prepared, options, camera, settings, reference_spp, cache);
            settings.samples_per_pixel = spp;
            std::vector<double> seconds[2], rel[2];
            for (int r = 0; r < repeats; ++r) {
                for (int k = 0; k < 2; ++k) {
                    options.quad_lights = kStrategies[k];
                    settings.seed = std::uint64_t(7 + r);
                    const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
                    const RenderResult result = render_paths(tracer, camera, settings);
                    seconds[k].push_back(result.seconds);
                    rel[k].push_back(compare(result.image, ref.image).relative_mse - ref.noise_relative_mse);
                }
            }
            for (int k = 0; k < 2; ++k) {
                double e = 0;
                for (double x : rel[k]) e += x / double(repeats);
                const double t = median(seconds[k]);
                std::printf("| %s | %s | %.3e | %.2f | %.1f s |\n",
                            std::filesystem::path(scene.file).filename().string().c_str(),
                            to_string(kStrategies[k]).data(), e, t, t * e / target);
            }
        }
        std::printf("\n%dx%d, %d threads, reference %d spp (its own relative MSE subtracted)\n", size, size,
                    threads, reference_spp);
        return 0;
    } catch (const InputError& e) {
        std::fprintf(stderr, "ch06_quad_lights: %s\n", e.what());
        return kExitBadInput;
    }
}
