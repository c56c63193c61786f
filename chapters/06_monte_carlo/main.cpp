// Chapter 06: Monte Carlo with importance sampling. An iterative path tracer whose directions are drawn by
// the strategy `--sampling uniform|cosine|brdf|light|mis`; `--irradiance` estimates E = ∫ L cos θ dω each way
// against its closed forms; `--converge` measures RMSE against samples per pixel and time for every strategy
// (CSV, log-log plots, efficiency table) against a converged reference cached as PFM.
#include <cmath>
#include <cstdio>
#include <string>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "05_recursive_gi/gi_render.hpp"
#include "convergence.hpp"
#include "irradiance_study.hpp"
#include "path_tracer.hpp"
#include "rt/app.hpp"
#include "rt/image_io.hpp"

namespace {

using namespace rt;

std::vector<std::string> light_notes(const Scene& scene) {
    std::vector<std::string> notes;
    if (!scene.point_lights.empty()) {
        notes.push_back(
            "point lights are deltas: only the light and mis strategies see them (no sampled direction hits "
            "a point)");
    }
    return notes;
}

}  // namespace

int main(int argc, char** argv) {
    std::string sampling = "mis";
    std::string sampler = "stratified";
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
                              "ch06_default.json", kRecursiveChapterEffects};
    auto flags = [&](CLI::App& app) {
        app.add_option("--sampling", sampling, "How directions are drawn: uniform|cosine|brdf|light|mis")
            ->check(CLI::IsMember({"uniform", "cosine", "brdf", "light", "mis"}));
        app.add_option(
               "--sampler", sampler,
               "Where a sample's numbers come from: independent|stratified|sobol (Owen-scrambled Sobol)")
            ->check(CLI::IsMember({"independent", "stratified", "sobol"}));
        app.add_option("--termination", termination,
                       "How a path ends (chapter 05): depth|throughput|roulette")
            ->check(CLI::IsMember({"depth", "throughput", "roulette"}));
        app.add_option("--max-depth", max_depth,
                       "Bounces at most (default: 8 with depth, else chapter 05's safety cap of 64)")
            ->check(CLI::Range(1, 1000));
        CLI::Option* irradiance_flag = app.add_flag(
            "--irradiance", irradiance,
            "Estimate E = integral of L cos theta over the hemisphere with each strategy against its "
            "closed form (a quad, a sphere, the sky), independent, stratified and Sobol points");
        app.add_option("--irradiance-runs", irradiance_runs, "With --irradiance: runs per row")
            ->check(CLI::Range(2, 100000))->check(only_with({{irradiance_flag}}));
        CLI::Option* converge_flag =
            app.add_flag("--converge", converge,
                         "RMSE against spp 1..--max-spp and time for every strategy, against a cached converged "
                         "reference: CSV, log-log plots (gnuplot) and the efficiency table");
        app.add_option("--max-spp", max_spp, "With --converge: the largest spp (a power of 2)")
            ->check(CLI::Range(1, 1 << 16))->check(power_of_two())->check(only_with({{converge_flag}}));
        app.add_option("--reference-spp", reference_spp, "With --converge: spp of the reference")
            ->check(CLI::Range(2, 1 << 20))->check(only_with({{converge_flag}}));
        app.add_option("--cache", cache, "With --converge: folder of the cached reference PFM")->check(only_with({{converge_flag}}));
        app.add_option("--csv", csv,
                       "With --converge: the CSV file; the plots go beside it (_spp.png, _time.png)")
            ->check(only_with({{converge_flag}}));
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
        options.sampler = point_set_from_string(sampler);
        options.termination.rule = termination_from_string(termination);
        // Roulette and the throughput rule end paths themselves; chapter 05's cap then only guards against a
        // path between two mirrors, high enough not to bias the result measurably.
        options.termination.max_depth =
            max_depth.value_or(options.termination.rule == Termination::kMaxDepth ? 8 : kSafetyDepthCap);
        options.simulated = context.simulated;
        const RenderScene prepared(scene, context.simulated);
        const LightSet& lights = prepared.lights;
        const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);

        if (converge) {
            check_writable("--csv", csv);
            std::printf("converged reference: %d spp (MIS), %dx%d ...\n", reference_spp, settings.width,
                        settings.height);
            std::fflush(stdout);
            const Reference ref =
                converged_reference(prepared, options, camera, settings, reference_spp, cache);
            std::printf("  %s %s; its own noise: MSE %.3e (RMSE %.3e)\n",
                        ref.cached ? "read" : "rendered and wrote", ref.file.string().c_str(), ref.noise_mse,
                        std::sqrt(ref.noise_mse));
            print_convergence_study(prepared, options, camera, settings, ref, max_spp, csv);
            return std::nullopt;
        }

        const PathTracer tracer(prepared.world, prepared.materials, lights, options);
        std::vector<std::string> notes = prepared.materials.notes();
        for (const std::string& note : light_notes(scene)) notes.push_back(note);
        ChapterRun run{render_paths(tracer, camera, settings), std::move(notes), std::nullopt};
        run.notes.push_back("sampling: " + sampling + ", sampler: " + sampler +
                            ", termination: " + termination);
        for (const std::string& u : lights.unsampled)
            run.notes.push_back("emitter not sampled as a light: " + u);
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
