// Chapter 05: recursive global illumination. Follows each camera ray's path bounce by bounce: emission,
// direct light (chapter 04), mirror reflection and one uniformly sampled indirect direction per diffuse
// bounce, until the termination rule (`--termination depth|throughput|roulette`) stops it. `--depth-study`
// measures what each rule's bias and noise cost against time in the furnace, whose exact answer is Le / (1 −
// ρ).
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "furnace.hpp"
#include "gi_notes.hpp"
#include "gi_render.hpp"
#include "rt/app.hpp"
#include "rt/assets.hpp"
#include "rt/errors.hpp"
#include "rt/image_io.hpp"
#include "rt/scene_loader.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    std::string rule_name = "roulette";
    std::optional<int> max_depth;
    Real min_throughput = Real(0.01);
    int roulette_start = 3;
    bool study = false;
    std::vector<int> study_depths{1, 2, 4, 8, 16};
    std::vector<Real> study_throughputs{Real(0.01), Real(0.1)};
    std::string csv;
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
        CLI::Option* rule_flag = app.add_option("--termination", rule_name,
                       "When a path stops: depth (after --max-depth bounces), throughput (below "
                       "--min-throughput) or roulette (Russian roulette, unbiased)")
            ->check(CLI::IsMember({"depth", "throughput", "roulette"}));
        app.add_option(
               "--max-depth", max_depth,
               "Bounces after the camera ray: the depth rule's N (default 8), a hard cap for the others "
               "(default 64)")
            ->check(CLI::Range(0, 1024));
        app.add_option("--min-throughput", min_throughput,
                       "The throughput rule's threshold on max(throughput) (default 0.01)")
            ->check(CLI::Range(0.0, 1.0))->check(only_with({{rule_flag, {"throughput"}}}));
        app.add_option("--roulette-start", roulette_start,
                       "Bounces before Russian roulette starts (default 3)")
            ->check(CLI::Range(0, 1024))->check(only_with({{rule_flag, {"roulette"}}, {study_flag}}));
        app.add_option("--study-depths", study_depths, "With --depth-study: the depths (default 1 2 4 8 16)")
            ->check(CLI::Range(0, 1024))->check(only_with({{study_flag}}));
        app.add_option("--study-throughputs", study_throughputs,
                       "With --depth-study: the throughput rule's thresholds (default 0.01 0.1)")
            ->check(CLI::Range(0.0, 1.0))->check(only_with({{study_flag}}));
        app.add_option("--csv", csv, "With --depth-study: also write the table as CSV")->check(only_with({{study_flag}}));
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        TerminationSettings termination;
        termination.rule = termination_from_string(rule_name);
        termination.max_depth =
            max_depth.value_or(termination.rule == Termination::kMaxDepth ? 8 : kSafetyDepthCap);
        termination.min_throughput = min_throughput;
        termination.roulette_start_depth = roulette_start;
        DirectOptions direct;
        direct.simulated = context.simulated;

        if (study) {
            if (!csv.empty()) check_writable("--csv", csv);
            std::optional<Scene> loaded;
            {
                const World probe(context.scene);
                if (!find_furnace(context.scene, probe)) loaded = load_scene(scene_path("ch05_furnace.json"));
            }
            const Scene& scene = loaded ? *loaded : context.scene;
            // The furnace file's own image size and samples, unless the flags set them.
            RenderSettings settings = context.settings;
            if (loaded && cli->count("--width") == 0) settings.width = loaded->image.width;
            if (loaded && cli->count("--height") == 0) settings.height = loaded->image.height;
            if (loaded && cli->count("--spp") == 0) settings.samples_per_pixel = loaded->image.spp;
            const World world(scene);
            const auto furnace = find_furnace(scene, world);
            if (!furnace)
                throw InputError(scene.file + ": --depth-study: not a furnace (a closed emissive box)");
            std::vector<TerminationSettings> rules;
            for (int d : study_depths)
                rules.push_back({Termination::kMaxDepth, d, min_throughput, roulette_start});
            const int cap = max_depth.value_or(kSafetyDepthCap);
            rules.push_back({Termination::kRussianRoulette, cap, min_throughput, roulette_start});
            for (Real t : study_throughputs)
                rules.push_back({Termination::kMinThroughput, cap, t, roulette_start});
            const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
            std::vector<DepthStudyRow> rows =
                depth_study(world, scene, *furnace, camera, settings, rules, direct);
            DirectOptions no_light_sampling = direct;
            no_light_sampling.simulated = direct.simulated.without({Effect::kDirect});
            for (const DepthStudyRow& r :
                 depth_study(world, scene, *furnace, camera, settings, rules, no_light_sampling)) {
                rows.push_back(r);
            }
            print_depth_study(rows, scene, *furnace, settings, csv);
            return std::nullopt;
        }

        const Scene& scene = context.scene;
        const RenderSettings& settings = context.settings;
        const World world(scene);
        const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
        const MaterialTable materials(scene, context.simulated);
        const DirectLighting shading(world, materials, collect_lights(scene), direct);
        const RecursiveTracer tracer(shading, GiOptions{termination});
        ChapterRun run{render_gi(tracer, camera, settings), {}, std::nullopt};
        run.notes = gi_notes(scene, shading, termination, run.result);
        if (const auto furnace = find_furnace(scene, world)) {
            run.exact = furnace_image(*furnace, settings.width, settings.height);
            run.notes.push_back(furnace_note(*furnace, termination, direct.simulates(Effect::kIndirect)));
        }
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
