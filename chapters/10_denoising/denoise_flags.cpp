#include "denoise_flags.hpp"

#include <string>
#include <tuple>
#include <vector>

#include "rt/flags/enum_flag.hpp"
#include "rt/flags/only_with.hpp"
#include "rt/flags/study_flags.hpp"

namespace rt {

DenoiseSettings DenoiseFlags::resolved(int threads) const {
    DenoiseSettings out = settings;
    out.bilateral.edges = edges;
    out.atrous.edges = edges;
    out.threads = threads;
    return out;
}

void add_denoise_flags(CLI::App& app, DenoiseFlags& flags) {
    add_termination_flags(app, flags.termination);
    CLI::Option* study_flag = app.add_flag(
        "--study", flags.study,
        "Measure the denoisers against a converged reference (error, SSIM, time, equal-error spp, "
        "bias, failure regions) instead of rendering an image");
    CLI::Option* denoiser_flag = add_enum_option(
        app, flags.denoiser, joined_names<Denoiser>() + " (default atrous: the best measured)");
    // The filters' parameters matter to the filter that takes them, and to the study (it runs both).
    auto filter = [&](std::vector<std::string> names) {
        return only_with({{denoiser_flag, names}, {study_flag}});
    };
    app.add_option("--levels", flags.settings.atrous.levels, "atrous: levels (taps 1, 2, 4, ... apart)")
        ->check(CLI::Range(1, 12))
        ->check(filter({"atrous"}));
    app.add_option("--sigma-spatial", flags.settings.bilateral.spatial, "bilateral: sigma_s in pixels")
        ->check(CLI::Range(0.5, 32.0))
        ->check(filter({"bilateral"}));
    EdgeStopping& edges = flags.edges;
    for (auto [name, value, help] :
         {std::tuple{"--sigma-colour", &edges.colour, "on colour, in standard deviations"},
          {"--sigma-normal", &edges.normal, "on the normal"},
          {"--sigma-depth", &edges.depth, "on depth, a fraction of it"},
          {"--sigma-albedo", &edges.albedo, "on the albedo"}}) {
        app.add_option(name, *value, std::string("Edge stopping ") + help)
            ->check(CLI::Range(0.0, 1e30))
            ->check(filter({"bilateral", "atrous"}));
    }
    const CLI::Validator with_study = only_with({{study_flag}});
    StudyOptions& study = flags.study_options;
    add_reference_spp_option(app, study.reference_spp, 1, {{study_flag}});
    add_study_option(app, kCacheOption, study.cache, {{study_flag}});
    app.add_option("--runs", study.runs, "With --study: independent runs for the bias")
        ->check(CLI::Range(2, 64))
        ->check(with_study);
    app.add_option("--crops", study.crops,
                   "With --study: write PNG crops of the failure regions into this folder")
        ->check(with_study);
    app.add_flag("--sweeps", study.sweeps, "With --study: also sweep the filters' parameters")
        ->check(with_study);
}

}  // namespace rt
