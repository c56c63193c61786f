// Chapter 09: participating media and subsurface scattering, by its own volumetric path loop: free
// flights through homogeneous media (spectral MIS for chromatic ones), the Henyey–Greenstein phase function,
// next-event estimation through media, and the random walk inside a dielectric's medium (subsurface
// scattering); `--distance-sampling` adds equiangular points toward the lights (alone or by MIS).
// `--walk-study` measures walk lengths against the mean free path and the albedo, `--knob-study` the error
// and time of a cap on scattering events and of Russian roulette in the medium, `--free-flight-study`
// spectral MIS against the naive per-channel density. As the course's most complete renderer it chooses per
// scene (`--tracer`, tracer_choice.hpp): chapter 08's combined tracer where mirrors or glass cast caustics,
// Cycles' volume sampling in fog.
#include "05_recursive_gi/termination_flags.hpp"
#include "06_monte_carlo/sampling_flags.hpp"
#include "media_materials.hpp"
#include "media_studies.hpp"
#include "rt/flags/enum_flag.hpp"
#include "rt/run/app.hpp"
#include "tracer_choice.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    MediumWalk walk;
    bool no_roulette = false;
    PathOptions options;
    TerminationFlags termination{options.termination, std::nullopt};
    TracerRule tracer = TracerRule::kAuto;
    const CLI::Option* distance_flag = nullptr;
    const CLI::Option* quad_lights_flag = nullptr;
    MediaStudies studies;
    const ChapterInfo chapter{
        "ch09_participating_media",
        "Chapter 09: participating media and subsurface scattering: free flight, Henyey-Greenstein, "
        "next-event estimation through media, the random walk",
        "ch09_default.json", kMediaChapterEffects};
    auto flags = [&](CLI::App& app) {
        app.add_option("--max-events", walk.max_events,
                       "End a path after this many scattering events in media")
            ->check(CLI::Range(1, 1 << 30));
        app.add_flag("--no-medium-roulette", no_roulette,
                     "No Russian roulette at scattering events in media");
        add_termination_flags(app, termination);
        add_sampling_flag(app, options.strategy, options.quad_lights);
        quad_lights_flag = app.get_option("--quad-lights");
        add_sampler_flag(app, options.sampler);
        distance_flag = add_enum_option(app, walk.distance,
                                        "Where light scattered along a medium's segments is looked for (with "
                                        "--tracer auto, mis in fog unless given): " +
                                            joined_names<DistanceSampling>());
        add_enum_option(app, tracer,
                        "auto: the strategy that pays on the scene (chapter 08's combined tracer where "
                        "mirrors or glass cast caustics, Cycles' volume sampling in fog), or paths as the "
                        "flags say: " +
                            joined_names<TracerRule>());
        add_media_study_flags(app, studies);
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        options.simulated = context.simulated;
        options.termination = termination.resolved(context.scene);
        walk.roulette = !no_roulette;
        if (studies.any()) {
            run_media_study(studies, context.scene, context.settings, options);
            return std::nullopt;
        }
        const GivenFlags given{distance_flag->count() > 0, quad_lights_flag->count() > 0,
                               options.termination != PathOptions{}.termination};
        return render_by_choice(tracer, context, options, walk, given);
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
