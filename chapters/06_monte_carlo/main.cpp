// Chapter 06: Monte Carlo with importance sampling. An iterative path tracer whose directions are drawn by
// the strategy `--sampling uniform|cosine|brdf|light|mis`; `--irradiance` estimates E = ∫ L cos θ dω each way
// against its closed forms; `--converge` measures RMSE against samples per pixel and time for every strategy
// (CSV, log-log plots, efficiency table) against a converged reference cached as PFM.
#include "01_ray_generation/camera.hpp"
#include "05_recursive_gi/gi_render.hpp"
#include "05_recursive_gi/termination_flags.hpp"
#include "convergence.hpp"
#include "irradiance_study.hpp"
#include "monte_carlo_notes.hpp"
#include "path_tracer.hpp"
#include "rt/flags/study_flags.hpp"
#include "rt/run/app.hpp"
#include "sampling_flags.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    PathOptions options;
    TerminationFlags termination{options.termination, std::nullopt};  // chapter 06's rule until --termination
    bool irradiance = false;
    int irradiance_runs = 200;
    bool converge = false;
    ConvergenceRequest converge_request;
    const ChapterInfo chapter{"ch06_monte_carlo",
                              "Chapter 06: Monte Carlo with importance sampling: an iterative path tracer, "
                              "five sampling strategies, MIS",
                              "ch06_default.json", kRecursiveChapterEffects};
    auto flags = [&](CLI::App& app) {
        add_sampling_flag(app, options.strategy, options.quad_lights);
        add_sampler_flag(app, options.sampler);
        add_termination_flags(app, termination);
        CLI::Option* irradiance_flag = app.add_flag(
            "--irradiance", irradiance,
            "Estimate E = integral of L cos theta over the hemisphere with each strategy against its "
            "closed form (a quad, a sphere, the sky), independent, stratified and Sobol points");
        app.add_option("--irradiance-runs", irradiance_runs, "With --irradiance: runs per row")
            ->check(CLI::Range(2, 100000))
            ->check(only_with({{irradiance_flag}}));
        CLI::Option* converge_flag = app.add_flag(
            "--converge", converge,
            "RMSE against spp 1..--max-spp and time for every strategy, against a cached converged "
            "reference: CSV, log-log plots (gnuplot) and the efficiency table");
        const CLI::Validator with_converge = only_with({{converge_flag}});
        app.add_option("--max-spp", converge_request.max_spp,
                       "With --converge: the largest spp (a power of 2)")
            ->check(CLI::Range(1, 1 << 16))
            ->check(power_of_two())
            ->check(with_converge);
        add_reference_spp_option(app, converge_request.reference_spp, 2, {{converge_flag}});
        add_study_option(app, kCacheOption, converge_request.cache, {{converge_flag}});
        add_study_option(app, kCsvOption, converge_request.csv, {{converge_flag}},
                         "With --converge: the CSV file; the plots go beside it (_spp.png, _time.png)");
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        if (irradiance) {
            print_irradiance_study(irradiance_runs);
            return std::nullopt;
        }
        const RenderSettings& settings = context.settings;
        options.termination = termination.resolved(context.scene);
        options.simulated = context.simulated;
        const RenderScene prepared(context.scene, context.simulated);
        const PinholeCamera camera =
            make_pinhole_camera(context.scene.camera, settings.width, settings.height);
        if (converge) {
            run_convergence_study(prepared, options, camera, settings, converge_request);
            return std::nullopt;
        }
        const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
        return ChapterRun{render_paths(tracer, camera, settings), monte_carlo_notes(prepared, options),
                          std::nullopt};
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
