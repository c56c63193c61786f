// Chapter 05: recursive global illumination. Follows each camera ray's path bounce by bounce: emission,
// direct light (chapter 04), mirror reflection and one uniformly sampled indirect direction per diffuse
// bounce, until the termination rule (`--termination depth|throughput|roulette`) stops it. `--depth-study`
// measures what each rule's bias and noise cost against time in the furnace, whose exact answer is Le / (1 −
// ρ).
#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "depth_study_report.hpp"
#include "furnace.hpp"
#include "gi_notes.hpp"
#include "gi_render.hpp"
#include "rt/flags/study_flags.hpp"
#include "rt/run/app.hpp"
#include "termination_flags.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    TerminationFlags termination;
    bool study = false;
    DepthStudyRequest study_request;
    const CLI::App* cli = nullptr;  // to ask which core flags were given
    const ChapterInfo chapter{
        "ch05_recursive_gi",
        "Chapter 05: recursive global illumination: mirrors, indirect light, termination",
        "ch05_default.json", kRecursiveChapterEffects};
    auto flags = [&](CLI::App& app) {
        cli = &app;
        CLI::Option* study_flag = app.add_flag(
            "--depth-study", study,
            "In the furnace (default ch05_furnace.json): mean, bias, RMSE and time for the depth rule "
            "at each of --study-depths, Russian roulette and the throughput rule");
        CLI::Option* rule_flag = add_termination_flags(app, termination);
        app.add_option("--min-throughput", termination.settings.min_throughput,
                       "The throughput rule's threshold on max(throughput) (default 0.01)")
            ->check(CLI::Range(0.0, 1.0))
            ->check(only_with({{rule_flag, {"throughput"}}}));
        app.add_option("--roulette-start", termination.settings.roulette_start_depth,
                       "Bounces before Russian roulette starts (default 3)")
            ->check(CLI::Range(0, 1024))
            ->check(only_with({{rule_flag, {"roulette"}}, {study_flag}}));
        app.add_option("--study-depths", study_request.depths,
                       "With --depth-study: the depths (default 1 2 4 8 16)")
            ->check(CLI::Range(0, 1024))
            ->check(only_with({{study_flag}}));
        app.add_option("--study-throughputs", study_request.throughputs,
                       "With --depth-study: the throughput rule's thresholds (default 0.01 0.1)")
            ->check(CLI::Range(0.0, 1.0))
            ->check(only_with({{study_flag}}));
        add_study_option(app, kCsvOption, study_request.csv, {{study_flag}});
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        if (study) {
            run_depth_study(context.scene, *cli, context.settings, context.simulated, termination,
                            study_request);
            return std::nullopt;
        }
        const TerminationSettings rule = termination.resolved(context.scene);
        const Scene& scene = context.scene;
        const RenderSettings& settings = context.settings;
        const World world(scene, world_options_for(context.simulated));
        const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
        const MaterialTable materials(scene, context.simulated);
        DirectOptions direct;
        direct.simulated = context.simulated;
        const DirectLighting shading(world, materials, collect_lights(scene), direct);
        const RecursiveTracer tracer(shading, GiOptions{rule});
        ChapterRun run{render_gi(tracer, camera, settings), {}, std::nullopt};
        run.notes = gi_notes(scene, shading, rule, run.result);
        if (const auto furnace = find_furnace(scene, world)) {
            run.exact = furnace_image(*furnace, settings.width, settings.height);
            run.notes.push_back(furnace_note(*furnace, rule, direct.simulates(Effect::kIndirect)));
        }
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
