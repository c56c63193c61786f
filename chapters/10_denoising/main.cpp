// Chapter 10: denoising. The path tracer of chapters 06 and 07 records feature buffers (albedo, normal,
// depth at the first vertex that is not a delta bounce) and the variance of every pixel; a joint bilateral
// filter or the edge-avoiding à-trous wavelet filter then smooths the noise within surfaces and keeps their
// edges. `--out d.png` writes d.png and d.pfm (denoised), d.noisy.pfm, d.albedo.pfm and d.normal.pfm.
// `--study` measures what the filters buy against a converged reference: error, SSIM, time, the samples plain
// path tracing needs for the same error, the bias, and where denoising loses.
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "09_participating_media/media_notes.hpp"
#include "09_participating_media/volume_path_tracer.hpp"
#include "denoise_flags.hpp"
#include "denoise_study.hpp"
#include "denoiser.hpp"
#include "feature_buffers.hpp"
#include "rt/run/app.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    DenoiseFlags denoising;
    const ChapterInfo chapter{
        "ch10_denoising",
        "Chapter 10: denoising: feature buffers and per-pixel variance from the path "
        "tracer, a joint bilateral and the edge-avoiding a-trous filter, measured",
        "ch10_default.json",
        kMediaChapterEffects,
        {".noisy", ".albedo", ".normal"},
        [&] {
            if (denoising.denoiser == Denoiser::kNone && !denoising.study) return "";
            return "chapter 10 denoises the whole image, which a piece of it is not: "
                   "--samples, --resume and several MPI ranks only with --denoiser none";
        }};
    auto flags = [&](CLI::App& app) { add_denoise_flags(app, denoising); };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        const RenderSettings& settings = context.settings;
        const DenoiseSettings denoise_settings = denoising.resolved(settings.threads);
        PathOptions options;
        options.simulated = context.simulated;
        options.termination = denoising.termination.resolved(context.scene);
        // A piece of a render (--samples, --resume, an MPI rank's share) is plain path tracing: the same
        // image as the noisy one of a whole render, without the features, to be merged by rt_merge.
        const SampleRange all{0, settings.samples_per_pixel};
        const std::string fog = environment_behind_fog_note(context.scene, context.simulated);
        if (settings.resume || (settings.samples && *settings.samples != all)) {
            ChapterRun piece{
                render_with_media(Renderer::kPaths, context.scene, context.simulated, settings, options),
                {"renderer: chapter 09's path loop with chapter 07's BSDFs and its media; a piece of the "
                 "render: no features, not denoised"},
                std::nullopt};
            if (!fog.empty()) piece.notes.push_back(fog);
            return piece;
        }
        if (denoising.study) {
            run_denoise_study(context.scene, settings, options, denoise_settings, denoising.study_options);
            return std::nullopt;
        }
        FeatureRender rendered = render_features(context.scene, settings, options);
        ChapterRun run{rendered.result,
                       {"renderer: chapter 09's path loop with chapter 07's BSDFs and its media, recording "
                        "albedo, normal and depth at the first non-delta vertex"},
                       std::nullopt};
        if (!fog.empty()) run.notes.push_back(fog);
        if (rendered.result.interrupted) {
            run.notes.push_back("interrupted: the partial image is written as it is, not denoised");
            return run;
        }
        const Denoised denoised = denoise(rendered.buffers, denoising.denoiser, denoise_settings);
        run.result.image = denoised.image;
        for (std::string& note :
             denoise_notes(denoising.denoiser, denoise_settings, denoised, rendered.result.seconds))
            run.notes.push_back(std::move(note));
        run.extra_images = {{".noisy", rendered.buffers.colour, true},
                            {".albedo", rendered.buffers.albedo, false},
                            {".normal", rendered.buffers.normal, false}};
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
