#include "rt/app.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <set>
#include <thread>

#include "rt/assets.hpp"
#include "rt/effects.hpp"
#include "rt/error_metrics.hpp"
#include "rt/errors.hpp"
#include "rt/image_io.hpp"
#include "rt/interrupt.hpp"
#include "rt/output_files.hpp"
#include "rt/render_identity.hpp"
#include "rt/scene_loader.hpp"
#include "rt/split_render.hpp"

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
        // A resumed render's sums hold the samples of the runs before it too.
        const double taken = r.sums.empty() ? double(r.samples) : double(r.sums.total_count());
        std::printf(
            "  interrupted: partial image with %.4g samples per pixel on average (every pixel has at least "
            "%d) of the %d asked for\n",
            taken / pixels, r.samples_per_pixel, samples_taken(s).size());
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

int run(int argc, char** argv, const ChapterInfo& chapter, const ChapterFlags& add_flags,
        const ChapterRender& render, const MpiSession& mpi) {
    CLI::App app(chapter.description, chapter.executable);
    CoreOptions options;
    add_core_flags(app, options);
    SplitOptions split;
    add_split_flags(app, split);
    std::set<std::string> core_flags;  // what a film records apart, or what does not shape the image
    for (const CLI::Option* option : app.get_options()) core_flags.insert(option->get_name());
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
    // The ranks of an MPI job on one machine share its cores.
    settings.threads =
        options.threads > 0
            ? options.threads
            : std::max(1, int(std::thread::hardware_concurrency()) / mpi.ranks_on_this_machine());
    settings.progress = options.quiet || !mpi.is_root() ? ProgressStyle::kNone : ProgressStyle::kAuto;
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
    for (const fs::path& path : {png, with_suffix(png, "", ".pfm"), with_suffix(png, "", ".film"),
                                 with_suffix(png, ".partial", ".png"), with_suffix(png, ".partial", ".pfm"),
                                 with_suffix(png, ".partial", ".film")}) {
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

    const FilmIdentity identity{chapter.executable,
                                scene_file.filename().string(),
                                scene_fingerprint(scene, scene_file),
                                chapter_flags_text(app, core_flags),
                                settings.width,
                                settings.height,
                                settings.samples_per_pixel,
                                settings.seed};
    const SplitPlan plan = plan_split(split, identity, mpi, settings);

    const EffectSet needed_effects = needed(scene);
    const RunContext context{scene, settings, needed_effects & chapter.supported};
    install_interrupt_handler();
    std::optional<ChapterRun> result = render(context);
    if (!result) return interrupt_requested() ? kExitInterrupted : kExitOk;
    mpi.gather(result->result);
    if (!mpi.is_root()) return result->result.interrupted ? kExitInterrupted : kExitOk;
    if (plan.writes_film) {
        result->notes.push_back("samples " + to_string(plan.whole) + " of the " +
                                std::to_string(settings.samples_per_pixel) + "-sample render" +
                                (plan.resumed ? ", resumed from " + split.resume : std::string()));
    }
    if (mpi.size() > 1) {
        result->notes.push_back("split among " + std::to_string(mpi.size()) + " MPI ranks, samples " +
                                to_string(plan.whole) + " (rays and samples are every rank's)");
    }

    const RenderResult& r = result->result;
    if (r.interrupted && r.samples == 0) {
        std::fprintf(stderr, "%s: interrupted before any sample was taken; nothing written\n",
                     chapter.executable);
        return kExitInterrupted;
    }
    check_finite(r.image);
    const fs::path png_out = r.interrupted ? with_suffix(png, ".partial", ".png") : png;
    const std::optional<Film> film = film_of(plan, r, mpi);
    const std::string written = write_outputs(r.image, png_out, film ? &*film : nullptr);
    // The summary speaks of every rank's samples, not rank 0's share.
    RenderSettings all_ranks = settings;
    all_ranks.samples = plan.whole;
    print_summary(chapter, RunContext{scene, all_ranks, context.simulated}, needed_effects, *result, reference,
                  written);
    return r.interrupted ? kExitInterrupted : kExitOk;
}

}  // namespace

int run_chapter(int argc, char** argv, const ChapterInfo& chapter, const ChapterFlags& add_flags,
                const ChapterRender& render) {
    std::optional<MpiSession> mpi;
    try {
        mpi.emplace();
        return run(argc, argv, chapter, add_flags, render, *mpi);
    } catch (const InputError& e) {
        // Every rank checks the same input and fails alike: rank 0 says why.
        if (!mpi || mpi->is_root()) std::fprintf(stderr, "%s: %s\n", chapter.executable, e.what());
        return kExitBadInput;
    } catch (const std::exception& e) {
        if (mpi && mpi->size() > 1) {
            std::fprintf(stderr, "%s: rank %d failed: %s\n", chapter.executable, mpi->rank(), e.what());
            mpi->abort(kExitFailure);
        }
        std::fprintf(stderr, "%s: failed: %s\n", chapter.executable, e.what());
        return kExitFailure;
    }
}

}  // namespace rt
