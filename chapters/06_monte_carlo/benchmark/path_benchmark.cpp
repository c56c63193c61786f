// What the path tracer costs, measured on the course's benchmark scene (cornell.json's Cornell box with a
// diffuse sphere, 600×600, MIS): samples (paths) per second on 1 and 2 threads (the median of `--repeats`
// renders), whether the image is bit-identical for both, and the time to a relative MSE of 1e-3 against a
// converged reference (cached as PFM in `--cache`). Targets: >= 3e6 samples/s on 2 threads, 2 threads >= 1.8×
// one thread.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "convergence.hpp"
#include "path_tracer.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/core/errors.hpp"
#include "rt/core/median.hpp"
#include "rt/flags/enum_flag.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/run/strict_flags.hpp"

namespace {

using namespace rt;

// The first line of /proc/loadavg: "1.23 0.98 0.75 …" (what else the machine is running).
std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return in ? one + " " + five + " " + fifteen : std::string("unknown");
}

bool identical(const Image& a, const Image& b) {
    return a.pixels().size() == b.pixels().size() &&
           std::equal(a.pixels().begin(), a.pixels().end(), b.pixels().begin());
}

// Samples per second on 1 and 2 threads (indexed by the count): the median of `repeats` renders of
// settings.samples_per_pixel, in wall-clock and in processor time; and the image of each count's last render.
struct Throughput {
    double rate[3] = {0, 0, 0}, cpu_rate[3] = {0, 0, 0};
    Image images[3];
};

Throughput measure_throughput(const PathTracer& tracer, const PinholeCamera& camera, RenderSettings settings,
                              int repeats) {
    const int size = settings.width, spp = settings.samples_per_pixel;
    Throughput out;
    std::uint64_t rays = 0;
    for (int threads : {1, 2}) {
        settings.threads = threads;
        std::vector<double> seconds, cpu_seconds;
        for (int r = 0; r < repeats; ++r) {
            const std::clock_t cpu_start = std::clock();
            RenderResult result = render_paths(tracer, camera, settings);
            cpu_seconds.push_back(double(std::clock() - cpu_start) / CLOCKS_PER_SEC);
            seconds.push_back(result.seconds);
            rays = result.rays.total();
            out.images[threads] = std::move(result.image);
        }
        out.rate[threads] = double(size) * size * spp / median(seconds);
        out.cpu_rate[threads] = double(size) * size * spp / median(cpu_seconds);
        std::printf(
            "  %d thread%s: %.3g samples/s, %.3g rays/s (median of %d renders of %d spp: %.3f s); %.3g "
            "samples per processor second\n",
            threads, threads == 1 ? " " : "s", out.rate[threads], double(rays) / median(seconds), repeats,
            spp, median(seconds), out.cpu_rate[threads]);
    }
    return out;
}

// One render with `settings`, its relative MSE to `ref` printed: its seconds.
double time_to_error(const PathTracer& tracer, const PinholeCamera& camera, const RenderSettings& settings,
                     const Reference& ref) {
    const RenderResult r = render_paths(tracer, camera, settings);
    const double reached = compare(r.image, ref.image).relative_mse - ref.noise_relative_mse;
    std::printf("  %d thread%s: %d spp in %.2f s, relative MSE %.3e (minus the reference's noise)\n",
                settings.threads, settings.threads == 1 ? " " : "s", settings.samples_per_pixel, r.seconds,
                reached);
    return r.seconds;
}

// The table of samples per second and time to `target` on 1 and 2 threads, and the targets met.
void print_summary(const Throughput& throughput, const std::array<double, 3>& time_to_target, double target,
                   bool same) {
    const double(&rate)[3] = throughput.rate;
    const double speedup = rate[2] / rate[1];
    std::printf("\n| threads | samples/s | time to relative MSE %.0e |\n|---|---|---|\n", target);
    for (int threads : {1, 2})
        std::printf("| %d | %.3g | %.2f s |\n", threads, rate[threads], time_to_target[std::size_t(threads)]);
    std::printf(
        "\ntargets: 2 threads >= 3e6 samples/s: %s (%.3g); 2 threads >= 1.8x one: %s (%.2fx); "
        "identical images: %s\n",
        rate[2] >= 3e6 ? "met" : "NOT met", rate[2], speedup >= 1.8 ? "met" : "NOT met", speedup,
        same ? "yes" : "NO");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("ch06_benchmark: path tracer samples per second and time to relative MSE 1e-3",
                 "ch06_benchmark");
    app.option_defaults()->always_capture_default();  // --help shows each flag's default
    std::string scene_file = scene_path("ch06_default.json").string();
    int size = 600, spp = 16, repeats = 3, reference_spp = 2048;
    std::string cache = ".";
    std::string sampling = "mis";
    double target = 1e-3;
    app.add_option("--scene", scene_file,
                   "Scene (default: ch06_default.json, the Cornell box, diffuse sphere)");
    app.add_option("--size", size, "Image width and height")->check(CLI::Range(8, 4096));
    app.add_option("--spp", spp, "Samples per pixel of each timed render")->check(CLI::Range(1, 1 << 16));
    app.add_option("--repeats", repeats, "Timed renders per thread count (the median is reported)")
        ->check(CLI::Range(1, 100));
    app.add_option("--reference-spp", reference_spp, "Samples per pixel of the converged reference")
        ->check(CLI::Range(2, 1 << 20));
    app.add_option("--cache", cache, "Folder of the cached reference PFM");
    app.add_option("--sampling", sampling, "uniform|cosine|brdf|light|mis")
        ->check(choices<SamplingStrategy>());
    app.add_option("--target", target, "The relative MSE to reach")->check(CLI::Range(1e-8, 1.0));
    if (const auto stop = rt::read_flags(app, argc, argv)) return *stop;
    try {
        const Scene scene = load_scene(scene_file);
        const RenderScene prepared(scene, EffectSet::all());
        PathOptions options;
        options.strategy = from_string<SamplingStrategy>(sampling);
        const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
        RenderSettings settings;
        settings.width = settings.height = size;
        settings.seed = 1;
        settings.progress = ProgressStyle::kNone;
        const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
        std::printf("ch06_benchmark: %s, %dx%d, %s, %u hardware threads, load average %s\n",
                    scene_file.c_str(), size, size, sampling.c_str(), std::thread::hardware_concurrency(),
                    load_average().c_str());

        settings.samples_per_pixel = spp;
        const Throughput throughput = measure_throughput(tracer, camera, settings, repeats);
        const double(&rate)[3] = throughput.rate;
        const double(&cpu_rate)[3] = throughput.cpu_rate;
        const Image(&images)[3] = throughput.images;
        const double speedup = rate[2] / rate[1];
        const bool same = identical(images[1], images[2]);
        std::printf("  2 threads / 1 thread: %.2fx; image bit-identical on 1 and 2 threads: %s\n", speedup,
                    same ? "yes" : "NO");
        // The processor time a sample costs, whoever else runs: when it is the same on 1 and 2 threads the
        // render itself adds no parallel overhead, and a wall-clock speed-up short of 2x is the machine's
        // other load.
        std::printf("  processor time per sample, 2 threads / 1 thread: %.2f; load average now: %s\n",
                    cpu_rate[1] / cpu_rate[2], load_average().c_str());

        // Time to a relative MSE of `target`: relative MSE falls like 1/spp, so the spp that reaches it is
        // predicted from the error at `spp` and then rendered to check.
        const Reference ref = converged_reference(prepared, options, camera, settings, reference_spp, cache);
        std::printf("  reference: %s %s (relative MSE of its own noise %.2e)\n",
                    ref.cached ? "read" : "rendered and wrote", ref.file.string().c_str(),
                    ref.noise_relative_mse);
        const double measured = compare(images[2], ref.image).relative_mse - ref.noise_relative_mse;
        const int needed = std::max(1, int(std::ceil(double(spp) * measured / target)));
        std::printf("  relative MSE at %d spp: %.3e -> about %d spp for %.0e\n", spp, measured, needed,
                    target);
        settings.samples_per_pixel = needed;
        std::array<double, 3> time_to_target{};
        for (int threads : {1, 2}) {
            settings.threads = threads;
            time_to_target[std::size_t(threads)] = time_to_error(tracer, camera, settings, ref);
        }
        print_summary(throughput, time_to_target, target, same);
        return 0;
    } catch (const InputError& e) {
        std::fprintf(stderr, "ch06_benchmark: %s\n", e.what());
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ch06_benchmark: failed: %s\n", e.what());
        return kExitFailure;
    }
}
