#include "media_studies.hpp"

#include <cstdio>

#include "rt/flags/only_with.hpp"
#include "rt/flags/study_flags.hpp"
#include "volume_path_tracer.hpp"
#include "walk_study.hpp"

namespace rt {
namespace {

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

void print_knob_study(const MediaStudies& studies, const Scene& scene, const RenderSettings& settings,
                      const PathOptions& options) {
    RenderSettings reference_settings = settings;
    reference_settings.samples_per_pixel = studies.reference_spp;
    reference_settings.seed = settings.seed + 1000;
    std::printf("reference: %d spp, no cap, %dx%d ...\n", studies.reference_spp, settings.width,
                settings.height);
    std::fflush(stdout);
    const Image reference = render_with_media(Renderer::kPaths, scene, options.simulated, reference_settings,
                                              options, {1 << 30, true})
                                .image;
    std::printf("%10s %9s %5s %12s %13s %10s\n", "max events", "roulette", "spp", "RMSE", "mean error",
                "time (s)");
    for (const WalkKnobRow& r : walk_knobs(scene, settings, options, reference, studies.caps)) {
        std::printf("%10d %9s %5d %12.4e %+13.4e %10.3f\n", r.max_events, r.roulette ? "on" : "off",
                    settings.samples_per_pixel, r.rmse, r.mean_error, r.seconds);
    }
}

}  // namespace

void add_media_study_flags(CLI::App& app, MediaStudies& studies) {
    CLI::Option* walk_flag = app.add_flag(
        "--walk-study", studies.walk,
        "Walk lengths and time against the mean free path and the albedo (a sphere of radius 1)");
    app.add_option("--study-paths", studies.walk_paths, "With --walk-study: paths per row")
        ->check(CLI::Range(1, 1 << 24))
        ->check(only_with({{walk_flag}}));
    CLI::Option* knob_flag = app.add_flag(
        "--knob-study", studies.knobs,
        "The scene's error (against an uncapped reference) and time for each --caps, roulette on and off");
    app.add_option("--caps", studies.caps, "With --knob-study: the caps on scattering events")
        ->check(CLI::Range(1, 1 << 30))
        ->check(only_with({{knob_flag}}));
    add_reference_spp_option(app, studies.reference_spp, 1, {{knob_flag}});
    app.add_flag("--free-flight-study", studies.free_flight,
                 "Spectral MIS against the naive per-channel density on a chromatic medium");
}

void run_media_study(const MediaStudies& studies, const Scene& scene, const RenderSettings& settings,
                     const PathOptions& options) {
    if (studies.walk) {
        print_walk_study(studies.walk_paths, settings.seed);
    } else if (studies.free_flight) {
        print_free_flight_study(settings.seed);
    } else if (studies.knobs) {
        print_knob_study(studies, scene, settings, options);
    }
}

}  // namespace rt
