#include "rt/run/app.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <set>
#include <thread>
#include <vector>

#include "rt/core/error_metrics.hpp"
#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/exr_file.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/output_files.hpp"
#include "rt/io/picture_compare.hpp"
#include "rt/io/run_files.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/live/live_view.hpp"
#include "rt/render/heat_maps.hpp"
#include "rt/render/interrupt.hpp"
#include "rt/run/large_allocations.hpp"
#include "rt/run/render_identity.hpp"
#include "rt/run/split_render.hpp"
#include "rt/run/strict_flags.hpp"

namespace rt {
namespace {

namespace fs = std::filesystem;

void add_core_flags(CLI::App& app, CoreOptions& o, const ChapterInfo& chapter) {
    const std::string executable = chapter.executable;
    app.add_option("--scene", o.scene,
                   "Scene file (JSON), or the name of one in assets/scenes/; default: " + std::string(chapter.default_scene));
    app.add_option("--out", o.out,
                   "Output image: x.png, with the linear radiance beside it as x.pfm; or x.exr (OpenEXR, "
                   "half floats), with the picture beside it as x.png; default: " +
                       executable + ".png in the current folder");
    app.add_flag("--exr-float", o.exr_float,
                 "With --out x.exr: floats (32 bits) instead of half floats (16 bits)");
    app.add_option("--width", o.width, "Image width in pixels; default: the scene's image.width")
        ->check(CLI::Range(1, kMaxImageSide));
    app.add_option("--height", o.height, "Image height in pixels; default: the scene's image.height")
        ->check(CLI::Range(1, kMaxImageSide));
    app.add_option("--spp", o.spp, "Samples per pixel; default: the scene's image.spp")
        ->check(CLI::Range(1, kMaxSamplesPerPixel));
    app.add_option("--seed", o.seed, "Random seed");
    app.add_option("--threads", o.threads, "Render threads (0: every core)")->check(CLI::Range(0, 1024));
    app.add_option("--reference", o.reference,
                   "Reference image to measure the error against: a PFM or EXR (radiance), or a PNG such as "
                   "a lesson's picture (the image's picture is compared with it, and where they differ is "
                   "shown)");
    app.add_option("--heat", o.heat,
                   "Also write what each pixel cost (PNG): rays per sample | bounces per sample (path length) | "
                   "samples, in false colour with their bars");
    app.add_flag("--quiet", o.quiet, "No progress bar");
}

void print_summary(const ChapterInfo& chapter, const RunContext& context, const EffectSet& needed,
                   const ChapterRun& run, const std::optional<Image>& reference,
                   const std::optional<Picture>& reference_picture, const std::string& written) {
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
        if (r.unsampled_pixels > 0) {
            const PixelRect& u = r.unsampled_region;
            std::printf(
                "  interrupted in the first pass: %llu of %.0f pixels have no sample and are black, all "
                "within "
                "x [%d, %d), y [%d, %d)\n",
                static_cast<unsigned long long>(r.unsampled_pixels), pixels, u.x0, u.x1, u.y0, u.y1);
        }
    }
    auto print_error = [&](const char* against, const Image& image) {
        const ErrorMetrics e = compare(r.image, image);
        std::printf("  error against %s: RMSE %.5g, relative MSE %.5g, mean error %+.5g\n", against, e.rmse,
                    e.relative_mse, e.mean_error);
    };
    if (run.exact) print_error("the exact image", *run.exact);
    if (reference) print_error("the reference", *reference);
    for (const ExtraImage& extra : run.extra_images) {
        if (!reference || !extra.radiance) continue;
        const ErrorMetrics e = compare(extra.image, *reference);
        std::printf("  error of the %s image against the reference: RMSE %.5g, relative MSE %.5g, mean error %+.5g\n",
                    extra.suffix.substr(1).c_str(), e.rmse, e.relative_mse, e.mean_error);
    }
    if (reference_picture) {
        // A PNG reference holds what a PNG shows: the image's own picture is compared with it, level by level.
        const PictureDifference d = compare_pictures(to_picture(r.image), *reference_picture, 0);
        std::printf("  picture against the reference picture:\n%s", describe(d, "    ").c_str());
    }
    std::printf("  image mean %.5g, all pixels finite: %s\n", r.image.mean(),
                r.image.all_finite() ? "yes" : "NO");
    std::printf("  wrote %s\n", written.c_str());
}

// The command line as read: the core flags, the split's, the live view's (the chapter's own stay in the
// CLI::App).
struct RunFlags {
    CoreOptions core;
    SplitOptions split;
    LiveOptions live;
    std::set<std::string> core_flags;  // what a film records apart, or what does not shape the image
};

// What --reference gave: a PFM's or an EXR's radiance, or a PNG's picture.
struct Reference {
    std::optional<Image> image;
    std::optional<Picture> picture;
};

// Adds every flag to `app` and reads the command line into `flags` and the chapter's own options. Returns
// the exit status when the command line asked for help instead of a run.
std::optional<int> read_command_line(CLI::App& app, RunFlags& flags, const ChapterInfo& chapter,
                                     const ChapterFlags& add_flags, int argc, char** argv) {
    app.option_defaults()->always_capture_default();  // --help shows each flag's default value
    add_core_flags(app, flags.core, chapter);
    add_split_flags(app, flags.split);
    add_live_flags(app, flags.live);
    for (const CLI::Option* option : app.get_options()) flags.core_flags.insert(option->get_name());
    if (add_flags) add_flags(app);
    return parse_strictly(app, argc, argv);
}

// Refuses flags that cannot go together: the live view (which renders whole, in one process, and writes
// nothing: live_view.hpp) with files or a split, --port without it, and a split of a render that renders
// whole.
void check_flag_combinations(CLI::App& app, const RunFlags& flags, const ChapterInfo& chapter,
                             const MpiSession& mpi) {
    const SplitOptions& split = flags.split;
    if (flags.live.live) {
        const std::pair<const char*, bool> not_with[] = {{"--out", !flags.core.out.empty()},
                                                         {"--heat", !flags.core.heat.empty()},
                                                         {"--samples", !split.samples.empty()},
                                                         {"--resume", !split.resume.empty()},
                                                         {"mpirun with several ranks", mpi.size() > 1}};
        for (const auto& [flag, given] : not_with) {
            if (given) {
                throw InputError(std::string("--live: writes no file and renders whole, in one process: not "
                                             "with ") + flag);
            }
        }
    } else if (app.get_option("--port")->count() > 0) {
        throw InputError("--port: is used only with --live");
    }
    const std::string renders_whole = chapter.renders_whole_because ? chapter.renders_whole_because() : "";
    if (!renders_whole.empty() && (!split.samples.empty() || !split.resume.empty() || mpi.size() > 1)) {
        const std::string split_by = !split.samples.empty() ? "--samples"
                                     : !split.resume.empty() ? "--resume"
                                                              : "mpirun with " + std::to_string(mpi.size()) + " ranks";
        throw InputError(split_by + ": " + renders_whole);
    }
}

// The size, samples, seed and threads of the render: a flag overrides the scene's image. The size is checked
// (check_image_size), naming whichever of the flags and the scene gave each side.
RenderSettings render_settings(const CoreOptions& options, const Scene& scene, const MpiSession& mpi) {
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
        const std::string from_scene = scene.file + ": image";
        const std::string source = options.width && options.height ? "--width/--height"
                                   : options.width                 ? "--width and " + from_scene + ".height"
                                   : options.height                ? from_scene + ".width and --height"
                                                                   : from_scene;
        throw InputError(source + ": " + e.what());
    }
    return settings;
}

// The image the run writes: --out (a .png or a .exr), or <executable>.png in the current folder.
ImageOutput output_image(const CoreOptions& options, const ChapterInfo& chapter) {
    const fs::path out =
        options.out.empty() ? fs::path(std::string(chapter.executable) + ".png") : fs::path(options.out);
    return image_output(out, options.exr_float);
}

// Every file this run may write, finished or partial, is one of its own and no input (a file the scene read,
// --reference, the --resume film), and is probed before the render starts: its staging file is created and
// removed (staged_file.hpp). (x.film only when the run writes one: a piece of a render, or a resumed one.)
void probe_outputs(CLI::App& app, const RunFlags& flags, const ChapterInfo& chapter, const ImageOutput& out,
                   const Scene& scene) {
    const CoreOptions& options = flags.core;
    const SplitOptions& split = flags.split;
    if (!options.heat.empty() && fs::path(options.heat).extension() != ".png")
        throw InputError("--heat: must end in .png, got " + shown(options.heat));
    std::vector<RunFile> outputs =
        image_outputs(out, !split.samples.empty() || !split.resume.empty(), chapter.extra_images);
    if (!options.heat.empty()) outputs.push_back({"--heat", "the heat maps", options.heat});
    if (const CLI::Option* csv = app.get_option_no_throw("--csv"); csv && csv->count() > 0)
        outputs.push_back({"--csv", "the table", csv->as<std::string>()});
    std::vector<RunFile> inputs;
    for (const SceneInput& input : scene.inputs) inputs.push_back({"--scene", input.what, input.path});
    if (!options.reference.empty()) inputs.push_back({"--reference", "the reference", options.reference});
    // The film --resume continues may be replaced by this run's own film, which holds all of its samples.
    const bool resume_replaced_by_film = std::any_of(outputs.begin(), outputs.end(), [&](const RunFile& f) {
        return !split.resume.empty() && f.path.extension() == ".film" && same_file(f.path, split.resume);
    });
    if (!split.resume.empty() && !resume_replaced_by_film)
        inputs.push_back({"--resume", "the film to resume", split.resume});
    check_outputs(outputs, inputs);
}

// --reference: a PFM or an EXR (radiance) or a PNG (a picture), of the image's size.
Reference read_reference(const fs::path& file, const RenderSettings& settings) {
    Reference reference;
    if (file.empty()) return reference;
    int width = 0, height = 0;
    try {
        if (file.extension() == ".png") {
            reference.picture = read_png(file);
            width = reference.picture->width;
            height = reference.picture->height;
        } else {
            reference.image = read_radiance(file, PfmPixels::kRadiance);
            width = reference.image->width();
            height = reference.image->height();
        }
    } catch (const InputError& e) {
        throw InputError(std::string("--reference: ") + e.what());
    }
    if (width != settings.width || height != settings.height) {
        throw InputError("--reference: " + shown(file) + ": must be the size of the image, " +
                         std::to_string(settings.width) + "x" + std::to_string(settings.height) + ", got " +
                         std::to_string(width) + "x" + std::to_string(height));
    }
    return reference;
}

// What a film of this run records to be told apart from other renders' (render_identity.hpp).
FilmIdentity film_identity(const CLI::App& app, const RunFlags& flags, const ChapterInfo& chapter,
                           const Scene& scene, const fs::path& scene_file, const RenderSettings& settings) {
    return FilmIdentity{chapter.executable,         scene_file.filename().string(),
                        scene_fingerprint(scene, scene_file), chapter_flags_text(app, flags.core_flags),
                        settings.width,             settings.height,
                        settings.samples_per_pixel, settings.seed};
}

// The rendered run, on rank 0 (every rank's samples gathered): its files (PNG, PFM, film, further images,
// heat maps), staged and renamed together, then the summary. Returns the exit status.
int write_files_and_summary(const ChapterInfo& chapter, const RunFlags& flags, const RunContext& context,
                            const SplitPlan& plan, const MpiSession& mpi, const Reference& reference,
                            const HeatMaps* heat_maps, const ImageOutput& out, ChapterRun& run) {
    for (const std::string& ignored : context.scene.notes) run.notes.push_back("ignored: " + ignored);
    if (plan.writes_film) {
        run.notes.push_back("samples " + to_string(plan.whole) + " of the " +
                            std::to_string(context.settings.samples_per_pixel) + "-sample render" +
                            (plan.resumed ? ", resumed from " + shown(flags.split.resume) : std::string()));
    }
    if (mpi.size() > 1) {
        run.notes.push_back("split among " + std::to_string(mpi.size()) + " MPI ranks, samples " +
                            to_string(plan.whole) + " (rays and samples are every rank's)");
    }
    const RenderResult& r = run.result;
    if (r.interrupted && r.samples == 0) {
        std::fprintf(stderr, "%s: interrupted before any sample was taken; nothing written\n",
                     chapter.executable);
        return interrupted_exit_status();
    }
    check_finite(r.image);
    const ImageOutput written_out = r.interrupted ? out.partial() : out;
    const std::optional<Film> film = film_of(plan, r, mpi);
    if (run.extra_images.size() != 0 && run.extra_images.size() != chapter.extra_images.size())
        throw std::logic_error("the chapter gave back images other than its ChapterInfo::extra_images");
    for (std::size_t i = 0; i < run.extra_images.size(); ++i) {
        if (run.extra_images[i].suffix != chapter.extra_images[i])
            throw std::logic_error("the chapter gave back images other than its ChapterInfo::extra_images");
    }
    const std::string written =
        write_outputs(r.image, written_out, film ? &*film : nullptr, run.extra_images);
    if (heat_maps)
        run.notes.push_back(heat_maps->write(flags.core.heat) + (mpi.size() > 1 ? " (this rank's samples)" : ""));
    // The summary speaks of every rank's samples, not rank 0's share.
    RenderSettings all_ranks = context.settings;
    all_ranks.samples = plan.whole;
    print_summary(chapter, RunContext{context.scene, all_ranks, context.simulated}, needed(context.scene), run,
                  reference.image, reference.picture, written);
    if (r.interrupted) return interrupted_exit_status();
    // A signal that came once the render was done: the complete image was written all the same.
    return status_after_writing(chapter.executable, "the complete image");
}

int run(int argc, char** argv, const ChapterInfo& chapter, const ChapterFlags& add_flags,
        const ChapterRender& render, const MpiSession& mpi) {
    // From the start: a signal during the checks makes the render stop at once (nothing written), and a
    // second one removes any staging file of the output probes.
    install_interrupt_handler();
    CLI::App app(chapter.description, chapter.executable);
    RunFlags flags;
    if (const std::optional<int> help = read_command_line(app, flags, chapter, add_flags, argc, argv))
        return *help;
    check_flag_combinations(app, flags, chapter, mpi);
    const fs::path scene_file =
        flags.core.scene.empty() ? scene_path(chapter.default_scene) : resolve_scene(flags.core.scene);
    const Scene scene = load_scene(scene_file);
    RenderSettings settings = render_settings(flags.core, scene, mpi);
    const ImageOutput out = output_image(flags.core, chapter);
    if (!flags.live.live) probe_outputs(app, flags, chapter, out, scene);
    const Reference reference = read_reference(flags.core.reference, settings);
    const SplitPlan plan =
        plan_split(flags.split, film_identity(app, flags, chapter, scene, scene_file, settings), mpi, settings);
    if (flags.live.live) {
        LiveKnobs knobs(app, flags.core_flags, std::vector<std::string>(argv + 1, argv + argc));
        return run_live(LiveRun{chapter, scene, settings, needed(scene), render, knobs, reference.image},
                        flags.live.port);
    }
    std::optional<HeatMaps> heat_maps;
    if (!flags.core.heat.empty()) settings.observer = &heat_maps.emplace(settings.width, settings.height);
    const RunContext context{scene, settings, simulated_effects(scene, chapter.supported)};
    std::optional<ChapterRun> result = render(context);
    set_interrupt_phase(InterruptPhase::kWriting);
    if (!result) return signal_received() ? interrupted_exit_status() : kExitOk;
    mpi.gather(result->result);
    if (!mpi.is_root()) return result->result.interrupted ? interrupted_exit_status() : kExitOk;
    return write_files_and_summary(chapter, flags, context, plan, mpi, reference,
                                   heat_maps ? &*heat_maps : nullptr, out, *result);
}

}  // namespace

int run_chapter(int argc, char** argv, const ChapterInfo& chapter, const ChapterFlags& add_flags,
                const ChapterRender& render) {
    map_large_allocations_apart();
    std::optional<MpiSession> mpi;
    try {
        mpi.emplace();
        return run(argc, argv, chapter, add_flags, render, *mpi);
    } catch (const InputError& e) {
        // Every rank checks the same input and fails alike: rank 0 says why. printable(): whatever the
        // message quotes (a flag's value in CLI11's words), it stays one line.
        if (!mpi || mpi->is_root())
            std::fprintf(stderr, "%s: %s\n", chapter.executable, printable(e.what()).c_str());
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr,
                     "%s: failed: out of memory (this machine's memory, or the limit set on this process, "
                     "ulimit -v, is too small for this run)\n",
                     chapter.executable);
        return kExitFailure;
    } catch (const std::exception& e) {
        if (mpi && mpi->size() > 1) {
            std::fprintf(stderr, "%s: rank %d failed: %s\n", chapter.executable, mpi->rank(),
                         printable(e.what()).c_str());
            mpi->abort(kExitFailure);
        }
        std::fprintf(stderr, "%s: failed: %s\n", chapter.executable, printable(e.what()).c_str());
        return kExitFailure;
    }
}

}  // namespace rt
