// Chapter 09: participating media and subsurface scattering, by its own volumetric path loop: free
// flights through homogeneous media (spectral MIS for chromatic ones), the Henyey–Greenstein phase function,
// next-event estimation through media, and the random walk inside a dielectric's medium (subsurface
// scattering). `--walk-study` measures walk lengths against the mean free path and the albedo,
// `--knob-study` the error and time of a cap on scattering events and of Russian roulette in the medium,
// `--free-flight-study` spectral MIS against the naive per-channel density.
#include <cstdio>
#include <string>
#include <vector>

#include "media_materials.hpp"
#include "rt/app.hpp"
#include "rt/errors.hpp"
#include "volume_path_tracer.hpp"
#include "walk_study.hpp"

namespace {

using namespace rt;

void print_walk_study(int paths, std::uint64_t seed) {
    const auto rows = walk_lengths({1, 0.1, 0.01}, {0.5, 0.9, 0.99, 0.999}, paths, seed);
    std::printf(
        "Random walks in a sphere of radius 1 (index-matched, g = 0, uniform sky of radiance 1), %d paths "
        "each\n",
        paths);
    std::printf("%10s %8s %16s %10s %14s %10s\n", "mfp", "albedo", "events per path", "longest",
                "ns per path", "radiance");
    for (const WalkLengthRow& r : rows) {
        std::printf("%10.3g %8.3f %16.2f %10llu %14.0f %10.4f\n", r.mean_free_path, r.albedo,
                    r.events_per_path, static_cast<unsigned long long>(r.longest), r.ns_per_path, r.radiance);
    }
}

void print_free_flight_study(std::uint64_t seed) {
    const Color sigma_t(0.25f, 1, 4);
    const Real t_max = 4;
    const auto rows = free_flight_study(sigma_t, t_max, {100, 1000, 10000, 100000}, 20, seed);
    std::printf(
        "Free flight in a chromatic medium, sigma_t = (0.25, 1, 4), albedo 1, t_max = 4: the estimate "
        "of P(scatter before t_max), 20 trials\n");
    std::printf("%8s %22s %22s %18s %18s\n", "samples", "rel. RMS error (MIS)", "rel. RMS error (naive)",
                "max weight (MIS)", "max weight (naive)");
    for (const FreeFlightRow& r : rows) {
        std::printf("%8d %22.4e %22.4e %18.3f %18.3f\n", r.samples, r.rms_error_average, r.rms_error_chosen,
                    r.max_weight_average, r.max_weight_chosen);
    }
}

}  // namespace

int main(int argc, char** argv) {
    int max_events = MediumWalk{}.max_events;
    bool no_roulette = false;
    std::string sampling = "mis";
    bool walk_study = false, knob_study = false, flight_study = false;
    int study_paths = 4000;
    std::vector<int> caps{1, 2, 4, 8, 16, 32, 64, 10000};
    int reference_spp = 1024;
    const ChapterInfo chapter{
        "ch09_participating_media",
        "Chapter 09: participating media and subsurface scattering: free flight, Henyey-Greenstein, "
        "next-event estimation through media, the random walk",
        "ch09_default.json", kMediaChapterEffects};
    auto flags = [&](CLI::App& app) {
        app.add_option("--max-events", max_events, "End a path after this many scattering events in media")
            ->check(CLI::Range(1, 1 << 30));
        app.add_flag("--no-medium-roulette", no_roulette,
                     "No Russian roulette at scattering events in media");
        app.add_option("--sampling", sampling,
                       "How chapter 06's loop draws directions: uniform|cosine|brdf|light|mis")
            ->check(CLI::IsMember({"uniform", "cosine", "brdf", "light", "mis"}));
        CLI::Option* walk_flag = app.add_flag(
            "--walk-study", walk_study,
            "Walk lengths and time against the mean free path and the albedo (a sphere of radius 1)");
        app.add_option("--study-paths", study_paths, "With --walk-study: paths per row")
            ->check(CLI::Range(1, 1 << 24))->check(only_with({{walk_flag}}));
        CLI::Option* knob_flag = app.add_flag(
            "--knob-study", knob_study,
            "The scene's error (against an uncapped reference) and time for each --caps, roulette on "
            "and off");
        app.add_option("--caps", caps, "With --knob-study: the caps on scattering events")
            ->check(CLI::Range(1, 1 << 30))->check(only_with({{knob_flag}}));
        app.add_option("--reference-spp", reference_spp, "With --knob-study: spp of the reference")
            ->check(CLI::Range(1, 1 << 20))->check(only_with({{knob_flag}}));
        app.add_flag("--free-flight-study", flight_study,
                     "Spectral MIS against the naive per-channel density on a chromatic medium");
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        const Scene& scene = context.scene;
        if (walk_study) {
            print_walk_study(study_paths, context.settings.seed);
            return std::nullopt;
        }
        if (flight_study) {
            print_free_flight_study(context.settings.seed);
            return std::nullopt;
        }
        PathOptions options;
        options.simulated = context.simulated;
        options.strategy = sampling_strategy_from_string(sampling);
        const MediumWalk walk{max_events, !no_roulette};
        if (knob_study) {
            RenderSettings reference_settings = context.settings;
            reference_settings.samples_per_pixel = reference_spp;
            reference_settings.seed = context.settings.seed + 1000;
            std::printf("reference: %d spp, no cap, %dx%d ...\n", reference_spp, context.settings.width,
                        context.settings.height);
            std::fflush(stdout);
            const Image reference =
                render_with_media(Renderer::kPaths, scene, context.simulated, reference_settings, options,
                                  {1 << 30, true})
                    .image;
            std::printf("%10s %9s %5s %12s %13s %10s\n", "max events", "roulette", "spp", "RMSE",
                        "mean error", "time (s)");
            for (const WalkKnobRow& r : walk_knobs(scene, context.settings, options, reference, caps)) {
                std::printf("%10d %9s %5d %12.4e %+13.4e %10.3f\n", r.max_events, r.roulette ? "on" : "off",
                            context.settings.samples_per_pixel, r.rmse, r.mean_error, r.seconds);
            }
            return std::nullopt;
        }
        const Renderer renderer = choose_renderer(context.simulated);
        ChapterRun run{render_with_media(renderer, scene, context.simulated, context.settings, options, walk),
                       {},
                       std::nullopt};
        run.notes.push_back(
            renderer == Renderer::kDirect
                ? std::string(to_string(renderer))
                : "renderer: paths (chapter 09's volumetric loop, chapter 07's BSDFs)");
        const MaterialTable materials(scene, context.simulated, media_materials());
        for (const std::string& note : materials.notes()) run.notes.push_back(note);
        run.notes.push_back("sampling: " + sampling + ", walk: at most " + std::to_string(max_events) +
                            " scattering events, roulette " + (no_roulette ? "off" : "on"));
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
