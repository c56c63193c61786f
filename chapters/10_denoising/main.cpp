// Chapter 10: denoising. The path tracer of chapters 06 and 07 records feature buffers (albedo, normal,
// depth at the first vertex that is not a delta bounce) and the variance of every pixel; a joint bilateral
// filter or the edge-avoiding à-trous wavelet filter then smooths the noise within surfaces and keeps their
// edges. `--out d.png` writes d.png and d.pfm (denoised), d.noisy.pfm, d.albedo.pfm and d.normal.pfm.
// `--study` measures what the filters buy against a converged reference: error, SSIM, time, the samples plain
// path tracing needs for the same error, the bias, and where denoising loses.
#include <cstdio>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "07_bsdf_refraction/bsdf_render.hpp"
#include "09_participating_media/volume_path_tracer.hpp"
#include "denoise_study.hpp"
#include "denoiser.hpp"
#include "feature_buffers.hpp"
#include "rt/app.hpp"
#include "rt/image_io.hpp"

namespace {

using namespace rt;

std::string describe(Denoiser denoiser, const DenoiseSettings& s) {
    if (denoiser == Denoiser::kNone) return "none";
    char text[200];
    const EdgeStopping& e = denoiser == Denoiser::kBilateral ? s.bilateral.edges : s.atrous.edges;
    if (denoiser == Denoiser::kAtrous) {
        std::snprintf(text, sizeof text, "atrous (%d levels", s.atrous.levels);
    } else {
        std::snprintf(text, sizeof text, "bilateral (sigma_s %g px", double(s.bilateral.spatial));
    }
    std::string out = text;
    std::snprintf(text, sizeof text, ", sigma colour %g, normal %g, depth %g, albedo %g)", double(e.colour),
                  double(e.normal), double(e.depth), double(e.albedo));
    return out + text;
}

}  // namespace

int main(int argc, char** argv) {
    std::string denoiser_name = "atrous";
    DenoiseSettings denoise_settings;
    EdgeStopping edges;
    bool study = false;
    StudyOptions study_options;
    const ChapterInfo chapter{"ch10_denoising",
                              "Chapter 10: denoising: feature buffers and per-pixel variance from the path "
                              "tracer, a joint bilateral and the edge-avoiding a-trous filter, measured",
                              "ch10_default.json",
                              kMediaChapterEffects,
                              {".noisy", ".albedo", ".normal"},
                              [&] {
                                  return denoiser_name == "none" && !study ? "" : "chapter 10 denoises the whole image, "
                                         "which a piece of it is not: --samples, --resume and several MPI ranks only "
                                         "with --denoiser none";
                              }};
    auto flags = [&](CLI::App& app) {
        CLI::Option* study_flag = app.add_flag(
            "--study", study,
            "Measure the denoisers against a converged reference (error, SSIM, time, equal-error spp, "
            "bias, failure regions) instead of rendering an image");
        CLI::Option* denoiser_flag = app.add_option("--denoiser", denoiser_name,
                       "none|bilateral|atrous (default atrous: the best measured)")
            ->check(CLI::IsMember({"none", "bilateral", "atrous"}));
        // The filters' parameters matter to the filter that takes them, and to the study (it runs both).
        auto filter = [&](std::vector<std::string> names) { return only_with({{denoiser_flag, names}, {study_flag}}); };
        app.add_option("--levels", denoise_settings.atrous.levels, "atrous: levels (taps 1, 2, 4, ... apart)")
            ->check(CLI::Range(1, 12))->check(filter({"atrous"}));
        app.add_option("--sigma-spatial", denoise_settings.bilateral.spatial, "bilateral: sigma_s in pixels")
            ->check(CLI::Range(0.5, 32.0))->check(filter({"bilateral"}));
        for (auto [name, value, help] : {std::tuple{"--sigma-colour", &edges.colour, "on colour, in standard deviations"},
                                         {"--sigma-normal", &edges.normal, "on the normal"},
                                         {"--sigma-depth", &edges.depth, "on depth, a fraction of it"},
                                         {"--sigma-albedo", &edges.albedo, "on the albedo"}}) {
            app.add_option(name, *value, std::string("Edge stopping ") + help)
                ->check(CLI::Range(0.0, 1e30))->check(filter({"bilateral", "atrous"}));
        }
        const CLI::Validator with_study = only_with({{study_flag}});
        app.add_option("--reference-spp", study_options.reference_spp, "With --study: spp of the reference")
            ->check(CLI::Range(1, 1 << 20))->check(with_study);
        app.add_option("--cache", study_options.cache, "With --study: folder of the cached reference PFM")->check(with_study);
        app.add_option("--runs", study_options.runs, "With --study: independent runs for the bias")
            ->check(CLI::Range(2, 64))->check(with_study);
        app.add_option("--crops", study_options.crops,
                       "With --study: write PNG crops of the failure regions into this folder")->check(with_study);
        app.add_flag("--sweeps", study_options.sweeps, "With --study: also sweep the filters' parameters")->check(with_study);
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        denoise_settings.bilateral.edges = edges;
        denoise_settings.atrous.edges = edges;
        denoise_settings.threads = context.settings.threads;
        PathOptions options;
        options.simulated = context.simulated;
        const Denoiser denoiser = denoiser_from_string(denoiser_name);
        // A piece of a render (--samples, --resume, an MPI rank's share) is plain path tracing: the same
        // image as the noisy one of a whole render, without the features, to be merged by rt_merge.
        const RenderSettings& settings = context.settings;
        const SampleRange all{0, settings.samples_per_pixel};
        if (settings.resume || (settings.samples && *settings.samples != all)) {
            return ChapterRun{
                render_with_media(Renderer::kPaths, context.scene, context.simulated, settings, options),
                {"renderer: chapter 09's path loop with chapter 07's BSDFs and its media; a piece of the render: "
                 "no features, not denoised"},
                std::nullopt};
        }
        if (study) {
            // Its outputs are probed before it renders (its cached reference: chapter 07's depth study).
            if (!study_options.crops.empty())
                check_writable("--crops", std::filesystem::path(study_options.crops) / "ch10_whole.png");
            run_denoise_study(context.scene, context.settings, options, denoise_settings, study_options);
            return std::nullopt;
        }
        FeatureRender rendered = render_features(context.scene, context.settings, options);
        ChapterRun run{rendered.result,
                       {"renderer: chapter 09's path loop with chapter 07's BSDFs and its media, recording "
                        "albedo, normal and depth at the first non-delta vertex"},
                       std::nullopt};
        if (rendered.result.interrupted) {
            run.notes.push_back("interrupted: the partial image is written as it is, not denoised");
            return run;
        }
        const Denoised denoised = denoise(rendered.buffers, denoiser, denoise_settings);
        run.result.image = denoised.image;
        char time[160];
        std::snprintf(time, sizeof time, "filter time %.3f s (the render %.3f s: %.1f%% more)",
                      denoised.seconds, rendered.result.seconds,
                      100.0 * denoised.seconds / std::max(rendered.result.seconds, 1e-9));
        run.notes.push_back("denoiser " + describe(denoiser, denoise_settings));
        run.notes.push_back(time);
        run.extra_images = {{".noisy", rendered.buffers.colour, true},
                            {".albedo", rendered.buffers.albedo, false},
                            {".normal", rendered.buffers.normal, false}};
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
