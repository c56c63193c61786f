#include "rt/app.hpp"

#include <algorithm>
#include <cstdio>
#include <thread>
#include <iostream>

#include "rt/assets.hpp"
#include "rt/effects.hpp"
#include "rt/error_metrics.hpp"
#include "rt/errors.hpp"
#include "rt/image_io.hpp"
#include "rt/interrupt.hpp"
#include "rt/scene_loader.hpp"

namespace rt {
namespace {

namespace fs = std::filesystem;

void add_core_flags(CLI::App& app, CoreOptions& o) {
    app.add_option("--scene", o.scene, "Scene file (JSON); default: the chapter's scene");
    app.add_option("--out", o.out, "Output PNG; the linear radiance is written beside it as .pfm");
    app.add_option("--width", o.width, "Image width in pixels")->check(CLI::Range(1, kMaxImageSide));
    app.add_option("--height", o.height, "Image height in pixels")->check(CLI::Range(1, kMaxImageSide));
    app.add_option("--spp", o.spp, "Samples per pixel")->check(CLI::Range(1, kMaxSamplesPerPixel));
    app.add_option("--seed", o.seed, "Random seed");
    app.add_option("--threads", o.threads, "Render threads (0: every core)")->check(CLI::Range(0, 1024));
    app.add_option("--reference", o.reference, "Reference image (PFM) to measure the error against");
    app.add_flag("--quiet", o.quiet, "No progress bar");
}

void print_summary(const ChapterInfo& chapter, const RunContext& context, const EffectSet& needed,
                   const ChapterRun& run, const std::optional<Image>& reference, const std::string& written) {
    const RenderResult& r = run.result;
    const RenderSettings& s = context.settings;
    std::printf("%s: %s, %dx%d, %d spp, seed %llu, %d threads\n", chapter.executable, context.scene.file.c_str(),
                s.width, s.height, s.samples_per_pixel, static_cast<unsigned long long>(s.seed), s.threads);
    std::printf("  effects needed:    %s\n", needed.to_string().c_str());
    std::printf("  effects supported: %s\n", chapter.supported.to_string().c_str());
    std::printf("  effects simulated: %s\n", context.simulated.to_string().c_str());
    for (int i = 0; i < kEffectCount; ++i) {
        const Effect e = Effect(i);
        if (needed.contains(e) && !chapter.supported.contains(e)) {
            std::printf("  effect skipped:    %s (simulated from %s on)\n", kEffectNames[std::size_t(i)].data(),
                        chapter_that_adds(e).c_str());
        }
    }
    for (const std::string& note : run.notes) std::printf("  note: %s\n", note.c_str());
    const double seconds = std::max(r.seconds, 1e-9);
    std::printf("  time %.3f s, %.3g samples/s, %.3g rays/s\n", r.seconds, double(r.samples) / seconds,
                double(r.rays.total()) / seconds);
    std::printf("  rays:");
    for (int k = 0; k < kRayKindCount; ++k) {
        std::printf(" %s %llu%s", kRayKindNames[std::size_t(k)].data(),
                    static_cast<unsigned long long>(r.rays.count[std::size_t(k)]), k + 1 < kRayKindCount ? "," : "");
    }
    std::printf(" (total %llu)\n", static_cast<unsigned long long>(r.rays.total()));
    if (r.interrupted) {
        std::printf("  interrupted: partial image with %d of %d samples per pixel\n", r.samples_per_pixel,
                    s.samples_per_pixel);
    }
    auto print_error = [&](const char* against, const Image& image) {
        const ErrorMetrics e = compare(r.image, image);
        std::printf("  error against %s: RMSE %.5g, relative MSE %.5g, mean error %+.5g\n", against, e.rmse,
                    e.relative_mse, e.mean_error);
    };
    if (run.exact) print_error("the exact image", *run.exact);
    if (reference) print_error("the reference", *reference);
    std::printf("  image mean %.5g, all pixels finite: %s\n", r.image.mean(), r.image.all_finite() ? "yes" : "NO");
    std::printf("  wrote %s\n", written.c_str());
}

fs::path with_suffix(const fs::path& png, const std::string& suffix, const std::string& extension) {
    fs::path p = png;
    p.replace_filename(png.stem().string() + suffix + extension);
    return p;
}

int run(int argc, char** argv, const ChapterInfo& chapter, const ChapterFlags& add_flags,
        const ChapterRender& render) {
    CLI::App app(chapter.description, chapter.executable);
    CoreOptions options;
    add_core_flags(app, options);
    if (add_flags) add_flags(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        throw InputError(std::string("usage: ") + e.what() + " (see --help)");
    }

    const fs::path scene_file = options.scene.empty() ? scene_path(chapter.default_scene) : fs::path(options.scene);
    const Scene scene = load_scene(scene_file);
    RenderSettings settings;
    settings.width = options.width.value_or(scene.image.width);
    settings.height = options.height.value_or(scene.image.height);
    settings.samples_per_pixel = options.spp.value_or(scene.image.spp);
    settings.seed = options.seed;
    settings.threads = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    settings.progress = options.quiet ? ProgressStyle::kNone : ProgressStyle::kAuto;
    check_image_size(settings.width, settings.height);

    const fs::path png = options.out.empty() ? fs::path(std::string(chapter.executable) + ".png") : fs::path(options.out);
    if (png.extension() != ".png") throw InputError("--out: " + png.string() + ": must end in .png");
    check_writable(png);
    std::optional<Image> reference;
    if (!options.reference.empty()) {
        reference = read_pfm(options.reference);
        if (reference->width() != settings.width || reference->height() != settings.height) {
            throw InputError(options.reference + ": reference is " + std::to_string(reference->width()) + "x" +
                             std::to_string(reference->height()) + " but the image is " +
                             std::to_string(settings.width) + "x" + std::to_string(settings.height));
        }
    }

    const EffectSet needed_effects = needed(scene);
    const RunContext context{scene, settings, needed_effects & chapter.supported};
    install_interrupt_handler();
    const std::optional<ChapterRun> result = render(context);
    if (!result) return kExitOk;

    const bool partial = result->result.interrupted;
    const fs::path png_out = partial ? with_suffix(png, ".partial", ".png") : png;
    const fs::path pfm_out = with_suffix(png_out, "", ".pfm");
    write_png(result->result.image, png_out);
    write_pfm(result->result.image, pfm_out);
    print_summary(chapter, context, needed_effects, *result, reference, png_out.string() + " and " + pfm_out.string());
    return partial ? 130 : kExitOk;
}

}  // namespace

int run_chapter(int argc, char** argv, const ChapterInfo& chapter, const ChapterFlags& add_flags,
                const ChapterRender& render) {
    try {
        return run(argc, argv, chapter, add_flags, render);
    } catch (const InputError& e) {
        std::fprintf(stderr, "%s: %s\n", chapter.executable, e.what());
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: failed: %s\n", chapter.executable, e.what());
        return kExitFailure;
    }
}

}  // namespace rt
