#include "rt/app.hpp"

#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <thread>

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

// 128 + SIGINT: what a shell reports for a program stopped by Ctrl-C.
constexpr int kExitInterrupted = 130;

void add_core_flags(CLI::App& app, CoreOptions& o) {
    app.add_option("--scene", o.scene, "Scene file (JSON); default: the chapter's scene");
    app.add_option("--out", o.out, "Output PNG; the linear radiance is written beside it as .pfm");
    app.add_option("--width", o.width, "Image width in pixels")->check(CLI::Range(1, kMaxImageSide));
    app.add_option("--height", o.height, "Image height in pixels")->check(CLI::Range(1, kMaxImageSide));
    app.add_option("--spp", o.spp, "Samples per pixel")->check(CLI::Range(1, kMaxSamplesPerPixel));
    // CLI11 would read -1 as 2^64 - 1 for an unsigned seed: refuse the sign instead.
    const CLI::Validator non_negative(
        [](std::string& text) {
            return text.starts_with('-') ? "must be a whole number >= 0, got " + text : "";
        },
        "NONNEGATIVE");
    app.add_option("--seed", o.seed, "Random seed")->check(non_negative);
    app.add_option("--threads", o.threads, "Render threads (0: every core)")->check(CLI::Range(0, 1024));
    app.add_option("--reference", o.reference, "Reference image (PFM) to measure the error against");
    app.add_flag("--quiet", o.quiet, "No progress bar");
}

void print_summary(const ChapterInfo& chapter, const RunContext& context, const EffectSet& needed,
                   const ChapterRun& run, const std::optional<Image>& reference, const std::string& written) {
    const RenderResult& r = run.result;
    const RenderSettings& s = context.settings;
    std::printf("%s: %s, %dx%d, %d spp, seed %llu, %d threads\n", chapter.executable,
                context.scene.file.c_str(), s.width, s.height, s.samples_per_pixel,
                static_cast<unsigned long long>(s.seed), s.threads);
    std::printf("  effects needed:    %s\n", needed.to_string().c_str());
    std::printf("  effects supported: %s\n", chapter.supported.to_string().c_str());
    std::printf("  effects simulated: %s\n", context.simulated.to_string().c_str());
    for (int i = 0; i < kEffectCount; ++i) {
        const Effect e = Effect(i);
        if (needed.contains(e) && !chapter.supported.contains(e)) {
            std::printf("  effect skipped:    %s (simulated from %s on)\n",
                        kEffectNames[std::size_t(i)].data(), chapter_that_adds(e).c_str());
        }
    }
    for (const std::string& note : run.notes) std::printf("  note: %s\n", note.c_str());
    const double seconds = std::max(r.seconds, 1e-9);
    std::printf("  time %.3f s, %.3g samples/s, %.3g rays/s\n", r.seconds, double(r.samples) / seconds,
                double(r.rays.total()) / seconds);
    std::printf("  rays:");
    for (int k = 0; k < kRayKindCount; ++k) {
        std::printf(" %s %llu%s", kRayKindNames[std::size_t(k)].data(),
                    static_cast<unsigned long long>(r.rays.count[std::size_t(k)]),
                    k + 1 < kRayKindCount ? "," : "");
    }
    std::printf(" (total %llu)\n", static_cast<unsigned long long>(r.rays.total()));
    if (r.interrupted) {
        const double pixels = double(s.width) * double(s.height);
        std::printf(
            "  interrupted: partial image with %.4g samples per pixel on average (every pixel has at least "
            "%d) of the %d asked for\n",
            double(r.samples) / pixels, r.samples_per_pixel, s.samples_per_pixel);
    }
    auto print_error = [&](const char* against, const Image& image) {
        const ErrorMetrics e = compare(r.image, image);
        std::printf("  error against %s: RMSE %.5g, relative MSE %.5g, mean error %+.5g\n", against, e.rmse,
                    e.relative_mse, e.mean_error);
    };
    if (run.exact) print_error("the exact image", *run.exact);
    if (reference) print_error("the reference", *reference);
    std::printf("  image mean %.5g, all pixels finite: %s\n", r.image.mean(),
                r.image.all_finite() ? "yes" : "NO");
    std::printf("  wrote %s\n", written.c_str());
}

fs::path with_suffix(const fs::path& png, const std::string& suffix, const std::string& extension) {
    fs::path p = png;
    p.replace_filename(png.stem().string() + suffix + extension);
    return p;
}

// No NaN or infinity may reach an image: one is a bug in the chapter, reported as a failure (exit 1).
void check_finite(const Image& image) {
    std::size_t bad = 0;
    int first_x = -1, first_y = -1;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (is_finite(image.at(x, y))) continue;
            if (bad++ == 0) first_x = x, first_y = y;
        }
    }
    if (bad > 0) {
        throw std::runtime_error("the render has " + std::to_string(bad) +
                                 " pixel(s) NaN or infinite (the first at x " + std::to_string(first_x) +
                                 ", y " + std::to_string(first_y) +
                                 "): a bug in the chapter; nothing written");
    }
}

// Writes the PNG and the PFM beside it, both or neither. Each is first written whole under a staging name,
// then both are renamed into place; SIGINT is held back meanwhile, so a second Ctrl-C (which exits at once)
// cannot leave a staging file behind: it takes effect when the files are complete.
void write_outputs(const Image& image, const fs::path& png, const fs::path& pfm) {
    sigset_t sigint, previous;
    sigemptyset(&sigint);
    sigaddset(&sigint, SIGINT);
    pthread_sigmask(SIG_BLOCK, &sigint, &previous);
    const std::string stage = ".staged-" + std::to_string(::getpid());
    const fs::path png_stage = png.string() + stage, pfm_stage = pfm.string() + stage;
    std::error_code ec;
    try {
        write_png(image, png_stage);
        write_pfm(image, pfm_stage);
        fs::rename(pfm_stage, pfm);
        fs::rename(png_stage, png);
    } catch (const std::exception& e) {
        fs::remove(png_stage, ec);
        fs::remove(pfm_stage, ec);
        pthread_sigmask(SIG_SETMASK, &previous, nullptr);
        // The messages of write_png and write_pfm name the staging file; name the file the user asked for.
        std::string what = e.what();
        for (const auto& [staged, final_path] : {std::pair{png_stage, png}, std::pair{pfm_stage, pfm}}) {
            for (auto at = what.find(staged.string()); at != std::string::npos;
                 at = what.find(staged.string())) {
                what.replace(at, staged.string().size(), final_path.string());
            }
        }
        throw std::runtime_error(what);
    }
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
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

    const fs::path scene_file =
        options.scene.empty() ? scene_path(chapter.default_scene) : fs::path(options.scene);
    const Scene scene = load_scene(scene_file);
    RenderSettings settings;
    settings.width = options.width.value_or(scene.image.width);
    settings.height = options.height.value_or(scene.image.height);
    settings.samples_per_pixel = options.spp.value_or(scene.image.spp);
    settings.seed = options.seed;
    settings.threads =
        options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    settings.progress = options.quiet ? ProgressStyle::kNone : ProgressStyle::kAuto;
    try {
        check_image_size(settings.width, settings.height);
    } catch (const InputError& e) {
        const bool from_flags = options.width || options.height;
        throw InputError((from_flags ? std::string("--width/--height") : scene_file.string() + ": image") +
                         ": " + e.what());
    }

    const fs::path png =
        options.out.empty() ? fs::path(std::string(chapter.executable) + ".png") : fs::path(options.out);
    if (png.extension() != ".png") throw InputError("--out: must end in .png, got " + png.string());
    // Every file this run may write, finished or partial, is checked before the render starts.
    for (const fs::path& path : {png, with_suffix(png, "", ".pfm"), with_suffix(png, ".partial", ".png"),
                                 with_suffix(png, ".partial", ".pfm")}) {
        try {
            check_writable(path);
        } catch (const InputError& e) {
            throw InputError(std::string("--out: ") + e.what());
        }
    }
    std::optional<Image> reference;
    if (!options.reference.empty()) {
        try {
            reference = read_pfm(options.reference);
        } catch (const InputError& e) {
            throw InputError(std::string("--reference: ") + e.what());
        }
        if (reference->width() != settings.width || reference->height() != settings.height) {
            throw InputError("--reference: " + options.reference + ": must be the size of the image, " +
                             std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                             ", got " + std::to_string(reference->width()) + "x" +
                             std::to_string(reference->height()));
        }
    }

    const EffectSet needed_effects = needed(scene);
    const RunContext context{scene, settings, needed_effects & chapter.supported};
    install_interrupt_handler();
    const std::optional<ChapterRun> result = render(context);
    if (!result) return interrupt_requested() ? kExitInterrupted : kExitOk;

    const RenderResult& r = result->result;
    if (r.interrupted && r.samples == 0) {
        std::fprintf(stderr, "%s: interrupted before any sample was taken; nothing written\n",
                     chapter.executable);
        return kExitInterrupted;
    }
    check_finite(r.image);
    const fs::path png_out = r.interrupted ? with_suffix(png, ".partial", ".png") : png;
    const fs::path pfm_out = with_suffix(png_out, "", ".pfm");
    write_outputs(r.image, png_out, pfm_out);
    print_summary(chapter, context, needed_effects, *result, reference,
                  png_out.string() + " and " + pfm_out.string());
    return r.interrupted ? kExitInterrupted : kExitOk;
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
