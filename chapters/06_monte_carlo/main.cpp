// Chapter 06: Monte Carlo with importance sampling. An iterative path tracer whose directions are drawn by
// the strategy `--sampling uniform|cosine|brdf|light|mis`; `--irradiance` estimates E = ∫ L cos θ dω each way
// against its closed forms; `--converge` measures RMSE against samples per pixel and time for every strategy
// (CSV, log-log plots, efficiency table) against a converged reference cached as PFM.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "camera.hpp"
#include "convergence.hpp"
#include "irradiance_study.hpp"
#include "path_tracer.hpp"
#include "rt/app.hpp"
#include "rt/errors.hpp"
#include "world.hpp"

namespace {

using namespace rt;

void print_irradiance_study(int runs) {
    const auto rows = irradiance_study({16, 256, 4096}, runs);
    std::printf(
        "E(p) = integral of L cos theta dw at p = 0, n = +z: %d runs per row, RMSE of one run's estimate\n",
        runs);
    std::printf("%-7s %10s %-8s %-11s %6s %12s %12s %12s %10s\n", "case", "exact", "strategy", "points", "N",
                "mean", "RMSE", "sigma", "efficiency");
    for (const auto& r : rows) {
        std::printf("%-7s %10.6f %-8s %-11s %6d %12.6f %12.3e %12.3e %10.3g\n", r.case_name.c_str(), r.exact,
                    to_string(r.strategy).data(), r.stratified ? "stratified" : "independent", r.samples,
                    r.mean, r.rmse, r.sigma, r.efficiency);
    }
}

std::vector<std::string> material_notes(const Scene& scene) {
    std::vector<std::string> notes;
    for (const Material& m : scene.materials) {
        if (m.type == MaterialType::kDielectric) {
            notes.push_back(
                "dielectric material '" + m.name +
                "': refraction is simulated from chapter 07 on; shaded as diffuse white (albedo 0.73)");
        }
    }
    if (!scene.point_lights.empty()) {
        notes.push_back(
            "point lights are deltas: only the light and mis strategies see them (no sampled direction hits "
            "a "
            "point)");
    }
    return notes;
}

}  // namespace

int main(int argc, char** argv) {
    std::string sampling = "mis";
    std::string termination = "roulette";
    std::optional<int> max_depth;
    bool irradiance = false;
    bool converge = false;
    int max_spp = 1024;
    int reference_spp = 8192;
    int irradiance_runs = 200;
    std::string cache = ".";
    std::string csv = "ch06_convergence.csv";
    const ChapterInfo chapter{"ch06_monte_carlo",
                              "Chapter 06: Monte Carlo with importance sampling: an iterative path tracer, "
                              "five sampling strategies, "
                              "MIS",
                              "ch06_default.json",
                              EffectSet{Effect::kCameraRays, Effect::kShadows, Effect::kDirect,
                                        Effect::kReflection, Effect::kGlossy, Effect::kIndirect}};
    auto flags = [&](CLI::App& app) {
        app.add_option("--sampling", sampling, "How directions are drawn: uniform|cosine|brdf|light|mis")
            ->check(CLI::IsMember({"uniform", "cosine", "brdf", "light", "mis"}));
        app.add_option("--termination", termination,
                       "How a path ends (chapter 05): depth|throughput|roulette");
        app.add_option("--max-depth", max_depth,
                       "Bounces at most (default: 8 with depth, else chapter 05's safety cap of 64)")
            ->check(CLI::Range(1, 1000));
        app.add_flag(
            "--irradiance", irradiance,
            "Estimate E = integral of L cos theta over the hemisphere with each strategy against its "
            "closed form (a quad, a sphere, the sky), independent and stratified");
        app.add_option("--irradiance-runs", irradiance_runs, "With --irradiance: runs per row")
            ->check(CLI::Range(2, 100000));
        app.add_flag("--converge", converge,
                     "RMSE against spp 1..--max-spp and time for every strategy, against a cached converged "
                     "reference: CSV, log-log plots (gnuplot) and the efficiency table");
        app.add_option("--max-spp", max_spp, "With --converge: the largest spp (a power of 2)")
            ->check(CLI::Range(1, 1 << 16));
        app.add_option("--reference-spp", reference_spp, "With --converge: spp of the reference")
            ->check(CLI::Range(2, 1 << 20));
        app.add_option("--cache", cache, "With --converge: folder of the cached reference PFM");
        app.add_option("--csv", csv,
                       "With --converge: the CSV file; the plots go beside it (_spp.png, _time.png)");
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        if (irradiance) {
            print_irradiance_study(irradiance_runs);
            return std::nullopt;
        }
        const Scene& scene = context.scene;
        const RenderSettings& settings = context.settings;
        PathOptions options;
        options.strategy = sampling_strategy_from_string(sampling);
        try {
            options.termination.rule = termination_from_string(termination);
        } catch (const InputError& e) {
            throw InputError(std::string("--termination: ") + e.what());
        }
        // Roulette and the throughput rule end paths themselves; chapter 05's cap then only guards against a
        // path between two mirrors, high enough not to bias the result measurably.
        options.termination.max_depth =
            max_depth.value_or(options.termination.rule == Termination::kMaxDepth ? 8 : kSafetyDepthCap);
        options.direct = context.simulated.contains(Effect::kDirect);
        options.shadows = context.simulated.contains(Effect::kShadows);
        options.indirect = context.simulated.contains(Effect::kIndirect);
        options.glossy = context.simulated.contains(Effect::kGlossy);
        const World world(scene);
        const LightSet lights = collect_lights(scene);
        const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);

        if (converge) {
            if (!std::filesystem::is_directory(cache))
                throw InputError("--cache: " + cache + ": not a folder");
            std::printf("converged reference: %d spp (MIS), %dx%d ...\n", reference_spp, settings.width,
                        settings.height);
            std::fflush(stdout);
            const Reference ref =
                converged_reference(world, scene, lights, options, camera, settings, reference_spp, cache);
            std::printf("  %s %s; its own noise: MSE %.3e (RMSE %.3e)\n",
                        ref.cached ? "read" : "rendered and wrote", ref.file.string().c_str(), ref.noise_mse,
                        std::sqrt(ref.noise_mse));
            const std::vector<SamplingStrategy> strategies(kAllStrategies.begin(), kAllStrategies.end());
            const auto rows =
                convergence_study(world, scene, lights, options, camera, settings, ref, strategies, max_spp);
            std::printf("%-8s %6s %12s %12s %12s %10s\n", "strategy", "spp", "RMSE", "MSE-noise", "rel. MSE",
                        "time (s)");
            for (const ConvergenceRow& r : rows) {
                std::printf("%-8s %6d %12.4e %12.4e %12.4e %10.4f\n", to_string(r.strategy).data(), r.spp,
                            r.rmse, r.mse, r.relative_mse, r.seconds);
            }
            const auto table = efficiency_table(rows);
            double uniform_efficiency = 0;
            for (const EfficiencyRow& e : table)
                if (e.strategy == SamplingStrategy::kUniform) uniform_efficiency = e.efficiency;
            std::printf("\nefficiency = 1 / (MSE x time) at %d spp (slope: of log RMSE against log spp)\n",
                        max_spp);
            std::printf("%-8s %8s %12s %10s %12s %12s\n", "strategy", "slope", "MSE", "time (s)",
                        "efficiency", "x uniform");
            for (const EfficiencyRow& e : table) {
                std::printf("%-8s %8.3f %12.4e %10.3f %12.4g %12.3g\n", to_string(e.strategy).data(), e.slope,
                            e.mse, e.seconds, e.efficiency,
                            uniform_efficiency > 0 ? e.efficiency / uniform_efficiency : 0.0);
            }
            write_convergence_csv(rows, csv);
            std::filesystem::path stem = csv;
            stem.replace_extension();
            const std::string title = std::filesystem::path(scene.file).filename().string() + ", " +
                                      std::to_string(settings.width) + "x" + std::to_string(settings.height);
            if (plot_convergence(csv, strategies, stem, title)) {
                std::printf("wrote %s, %s_spp.png and %s_time.png\n", csv.c_str(), stem.c_str(),
                            stem.c_str());
            } else {
                std::printf("wrote %s; gnuplot is not installed, so no plot (apt-get install gnuplot-nox)\n",
                            csv.c_str());
            }
            return std::nullopt;
        }

        const PathTracer tracer(world, scene, lights, options);
        ChapterRun run{render_paths(tracer, camera, settings), material_notes(scene), std::nullopt};
        run.notes.push_back("sampling: " + sampling + ", termination: " + termination);
        for (const std::string& u : lights.unsampled)
            run.notes.push_back("emitter not sampled as a light: " + u);
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
