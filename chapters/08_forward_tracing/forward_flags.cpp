#include "forward_flags.hpp"

#include "04_direct_lighting/quad_lights_flag.hpp"
#include "06_monte_carlo/sampling_flags.hpp"
#include "rt/flags/enum_flag.hpp"
#include "rt/flags/only_with.hpp"
#include "rt/flags/study_flags.hpp"

namespace rt {

LightTracerOptions ForwardFlags::light_tracer(const EffectSet& simulated) const {
    LightTracerOptions options;
    options.simulated = simulated;
    options.variant = variant;
    options.aperture_radius = aperture;
    options.paths = caustics_only ? LightPathSet::kCaustics : LightPathSet::kAll;
    return options;
}

std::string ForwardFlags::renders_whole_because() const {
    if (tracer == Tracer::kForward)
        return "forward tracing splats each light path into whichever pixels it reaches, so the image has "
               "no samples per pixel to split: it renders whole; --tracer reverse can be split";
    if (tracer == Tracer::kCombined)
        return "the combined tracer adds light paths splatted into any pixel: it renders whole; --tracer "
               "reverse can be split";
    return "";
}

void add_forward_flags(CLI::App& app, ForwardFlags& flags) {
    CLI::Option* tracer_flag =
        add_enum_option(app, flags.tracer,
                        "forward (light paths), reverse (chapter 07's renderer for the effects simulated) or "
                        "combined (chapter 06's paths, and light paths for the caustics the camera sees)");
    const CLI::Validator combined = only_with({{tracer_flag, {"combined"}}});
    app.add_option("--light-paths", flags.combined.light_paths_per_sample,
                   "With --tracer combined: light paths for the caustics per camera sample")
        ->check(CLI::Range(0.0, 1024.0))
        ->check(combined);
    app.add_option("--caustic-bounces", flags.combined.caustic_bounces,
                   "With --tracer combined: light paths carry the paths that meet glass or a mirror "
                   "after at most this many diffuse bounces from the camera (E D{1..K} S ...)")
        ->check(CLI::Range(1, kSafetyDepthCap))
        ->check(combined);
    CLI::Option* sampler_flag = add_sampler_flag(app, flags.combined.paths.sampler);
    add_quad_lights_flag(app, flags.combined.paths.quad_lights);
    sampler_flag
        ->description("With --tracer combined: where a camera sample's numbers come from: " +
                      joined_names<PointSet>())
        ->check(combined);
    CLI::Option* variant_flag =
        add_enum_option(app, flags.variant,
                        "How forward paths reach the camera: connect (every vertex to the pinhole) or "
                        "aperture (through a lens of radius --aperture)");
    app.add_option("--aperture", flags.aperture, "With --variant aperture: the lens radius, scene units")
        ->check(CLI::PositiveNumber)
        ->check(only_with({{variant_flag, {"aperture"}}}));
    app.add_flag("--caustics-only", flags.caustics_only,
                 "Forward: only light that arrived straight from a mirror or glass (paths L...S D E)")
        ->check(only_with({{variant_flag, {"connect"}}}));
    CLI::Option* study_flag = app.add_flag(
        "--forward-study", flags.study,
        "Measure on chapter 06's Cornell box the fraction of light paths that contribute and the "
        "time to chapter 06's RMSE; and where forward tracing wins and loses (ch08_default.json, "
        "ch08_mirror.json)");
    const CLI::Validator with_study = only_with({{study_flag}});
    StudyOptions& study = flags.study_options;
    app.add_option("--study-size", study.size, "With --forward-study: image side in pixels")
        ->check(CLI::Range(8, 1024))
        ->check(with_study);
    app.add_option("--study-paths", study.fraction_paths, "With --forward-study: light paths per fraction")
        ->check(CLI::Range(1000, 1 << 30))
        ->check(with_study);
    add_reference_spp_option(app, study.reference_spp, 2, {{study_flag}},
                             "With --forward-study: spp of chapter 06's converged reference");
    app.add_option("--glass-reference-spp", study.glass_reference_spp,
                   "With --forward-study: spp of the mirror and glass scenes' references")
        ->check(CLI::Range(2, 1 << 20))
        ->check(with_study);
    add_study_option(app, kCacheOption, study.cache, {{study_flag}},
                     "With --forward-study: folder of the converged references (chapter 06's cache files)");
    add_study_option(app, kCsvOption, study.csv, {{study_flag}},
                     "With --forward-study: also write the time-to-RMSE table as CSV");
}

}  // namespace rt
