// Time to a given error on the course's benchmark scene (not a test): `ch08_time_to_error` renders
// cornell.json (the glass Cornell box) with each strategy (chapter 07's paths and the combined tracer of
// combined_render.hpp, each K and R, each sampler) at doubling spp, in turn (strategy after strategy at
// each spp, --repeats renders each with their own seeds), against a converged reference (two halves of
// chapter 07's path tracer, cached as PFM: the files ch07_error_study makes; the reference's own noise,
// mean((A − r)² / (r² + 0.01)), is subtracted). It prints every render's relative MSE and seconds, and each
// strategy's time to a relative MSE of --target: interpolated in log–log between the two spp around it, or
// marked "extrapolated" (relative MSE ∝ 1 / time from the nearest point) when the spp it measured do not
// reach it; and its convergence rate, the exponent k of relative MSE ∝ spp^k fitted to its points. A
// strategy stops at the first spp whose renders reached the target, or whose median render took
// longer than --max-seconds.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include "07_bsdf_refraction/benchmark/reference_halves.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "combined_render.hpp"
#include "forward_study.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/core/median.hpp"
#include "rt/flags/enum_flag.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/run/strict_flags.hpp"

namespace {

using namespace rt;

struct Strategy {
    std::string name;
    std::function<RenderResult(const RenderSettings&)> render;
    std::vector<double> seconds = {}, relative_mse = {};  // per spp: median seconds, mean relative MSE
    bool done = false;
};

// The convergence rate k of relative MSE ∝ spp^k: the least-squares slope of log relMSE against log spp over
// the measured points (spp = first, 2 first, 4 first, …). 1/N Monte Carlo gives k = −1.
double convergence_rate(const std::vector<double>& relative_mse, int first_spp) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
    for (std::size_t i = 0; i < relative_mse.size(); ++i) {
        if (!(relative_mse[i] > 0)) continue;
        const double x = std::log(double(first_spp) * std::pow(2.0, double(i))), y = std::log(relative_mse[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        n += 1;
    }
    const double d = n * sxx - sx * sx;
    return n >= 2 && d > 0 ? (n * sxy - sx * sy) / d : 0.0;
}

// The load average of the last minute (what else the machine runs).
std::string load_average() {
    std::FILE* f = std::fopen("/proc/loadavg", "r");
    if (!f) return "unknown";
    char line[64] = {0};
    const bool read = std::fgets(line, sizeof line, f) != nullptr;
    std::fclose(f);
    if (!read) return "unknown";
    std::string s(line);
    return s.substr(0, s.find(' '));
}

// Chapter 07's paths with each sampler, then the combined tracer with each sampler, K and R.
std::vector<Strategy> make_strategies(const Scene& scene, EffectSet simulated,
                                      const std::vector<std::string>& samplers,
                                      const std::vector<int>& caustic_bounces,
                                      const std::vector<double>& light_paths) {
    std::vector<Strategy> strategies;
    for (const std::string& sampler : samplers) {
        PathOptions options;
        options.sampler = from_string<PointSet>(sampler);
        strategies.push_back({"paths, " + sampler, [&scene, simulated, options](const RenderSettings& s) {
                                  return render_with(Renderer::kPaths, scene, simulated, s, options);
                              }});
    }
    for (const std::string& sampler : samplers) {
        for (int bounces : caustic_bounces) {
            for (double ratio : light_paths) {
                CombinedOptions options;
                options.paths.sampler = from_string<PointSet>(sampler);
                options.caustic_bounces = bounces;
                options.light_paths_per_sample = Real(ratio);
                char name[96];
                std::snprintf(name, sizeof name, "combined, %s, K %d, R %g", sampler.c_str(), bounces, ratio);
                strategies.push_back({name, [&scene, simulated, options](const RenderSettings& s) {
                                          return render_combined(scene, simulated, s, options).render;
                                      }});
            }
        }
    }
    return strategies;
}

// What a measurement of the strategies needs: the reference, its noise, the spp and the stopping rules.
struct Measurement {
    const Image& reference;
    double noise;
    int first_spp, repeats;
    double target, max_seconds;
};

// Every strategy at doubling spp, in turn, --repeats renders each: the median seconds and mean relative MSE
// (less the reference's noise) of each, printed as measured, until the target or --max-seconds stops it.
void measure(std::vector<Strategy>& strategies, RenderSettings& settings, const Measurement& m) {
    std::printf("\n%-40s %6s %10s %12s\n", "strategy", "spp", "seconds", "rel. MSE");
    for (int spp = m.first_spp; spp <= (1 << 16); spp *= 2) {
        bool any = false;
        for (Strategy& strategy : strategies) {
            if (strategy.done) continue;
            any = true;
            std::vector<double> seconds, errors;
            for (int rep = 0; rep < m.repeats; ++rep) {
                settings.samples_per_pixel = spp;
                settings.seed = std::uint64_t(7 + rep);
                const RenderResult result = strategy.render(settings);
                seconds.push_back(result.seconds);
                errors.push_back(std::max(0.0, compare(result.image, m.reference).relative_mse - m.noise));
            }
            const double t = median(seconds);
            const double e = std::accumulate(errors.begin(), errors.end(), 0.0) / double(errors.size());
            strategy.seconds.push_back(t);
            strategy.relative_mse.push_back(e);
            std::printf("%-40s %6d %10.2f %12.4e\n", strategy.name.c_str(), spp, t, e);
            std::fflush(stdout);
            strategy.done = e <= m.target || t > m.max_seconds;
        }
        if (!any) break;
    }
}

// Each strategy's time to the target relative MSE and its convergence rate.
void print_times_to_target(const std::vector<Strategy>& strategies, double target, int first_spp) {
    std::printf("\n%-40s %22s %22s\n", "strategy", "time to target", "rate: rel. MSE ~ spp^k");
    for (const Strategy& strategy : strategies) {
        // time_to_rmse works on RMSE-like values: the square root of the relative MSE.
        std::vector<double> root(strategy.relative_mse.size());
        for (std::size_t i = 0; i < root.size(); ++i) root[i] = std::sqrt(strategy.relative_mse[i]);
        const double t = time_to_rmse(strategy.seconds, root, std::sqrt(target));
        const bool bracketed = strategy.relative_mse.front() >= target && strategy.relative_mse.back() <= target;
        std::printf("%-40s %10.1f s%-15s k = %.2f\n", strategy.name.c_str(), t, bracketed ? "" : " (extrapolated)",
                    convergence_rate(strategy.relative_mse, first_spp));
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("ch08_time_to_error: time to a relative MSE on the glass Cornell box, for each strategy",
                 "ch08_time_to_error");
    app.option_defaults()->always_capture_default();
    int size = 300, first_spp = 16, reference_spp = 8192, threads = 2, repeats = 2;
    double target = 1e-3, max_seconds = 120;
    std::string cache = ".";
    std::vector<double> light_paths{0.5, 1};
    std::vector<int> caustic_bounces{kSafetyDepthCap};
    std::vector<std::string> samplers{"stratified", "sobol"};
    app.add_option("--size", size, "Width and height of the renders")->check(CLI::Range(8, 4096));
    app.add_option("--first-spp", first_spp, "The first spp; each next one doubles it")
        ->check(CLI::Range(1, 1 << 16));
    app.add_option("--reference-spp", reference_spp, "Samples per pixel of the reference (two halves)")
        ->check(CLI::Range(2, 1 << 20));
    app.add_option("--threads", threads, "Render threads")->check(CLI::Range(1, 1024));
    app.add_option("--repeats", repeats, "Renders of each strategy at each spp")->check(CLI::Range(1, 100));
    app.add_option("--target", target, "The relative MSE to reach")->check(CLI::Range(1e-8, 1.0));
    app.add_option("--max-seconds", max_seconds, "A strategy stops after a render this long (median)")
        ->check(CLI::PositiveNumber);
    app.add_option("--light-paths", light_paths, "The combined tracer's light paths per camera sample to try")
        ->check(CLI::Range(0.0, 1024.0));
    app.add_option("--caustic-bounces", caustic_bounces,
                   "The combined tracer's K to try (light paths carry the paths E D{1..K} S ...)")
        ->check(CLI::Range(1, kSafetyDepthCap));
    app.add_option("--samplers", samplers, "The samplers to try")
        ->check(choices<PointSet>());
    app.add_option("--cache", cache, "Folder of the cached reference PFMs")->check(CLI::ExistingDirectory);
    if (const auto stop = rt::read_flags(app, argc, argv)) return *stop;

    try {
        SceneBenchmark box(size, threads, reference_spp, cache);
        const double noise = box.reference.noise;
        std::printf(
            "ch08_time_to_error: cornell.json %dx%d, %d threads, %d repeats; reference %d spp of chapter 07 "
            "(its relative MSE %.2e, subtracted); target relative MSE %.1e; load %s\n",
            size, size, threads, repeats, reference_spp, noise, target, load_average().c_str());

        std::vector<Strategy> strategies =
            make_strategies(box.scene, box.simulated, samplers, caustic_bounces, light_paths);
        measure(strategies, box.settings,
                Measurement{box.reference.image, noise, first_spp, repeats, target, max_seconds});
        print_times_to_target(strategies, target, first_spp);
        std::printf("load %s\n", load_average().c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ch08_time_to_error: %s\n", e.what());
        return 1;
    }
    return 0;
}
