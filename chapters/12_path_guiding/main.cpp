// Chapter 12: path guiding. Chapter 06's path tracer (chapter 07's materials) learns where the light comes
// from: training passes of 1, 2, 4, … samples per pixel record the radiance their paths carried into a
// spatial binary tree of directional quadtrees (Practical Path Guiding), and each vertex then draws its
// continuation from the learned distribution or the BSDF, by one-sample MIS. `--training-passes 0` renders
// chapter 06's unguided paths; the summary gives each pass's rays and the trees' memory; `--guide-picture`
// draws what the guide learned at a point beside the light that arrives there.
#include "05_recursive_gi/termination_flags.hpp"
#include "06_monte_carlo/sampling_flags.hpp"
#include "07_bsdf_refraction/refraction_notes.hpp"
#include "guiding_flags.hpp"
#include "rt/io/image_io.hpp"
#include "rt/run/app.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    PathOptions options;
    TerminationFlags termination{options.termination, std::nullopt};
    GuidedRenderOptions guided;
    GuidePictureRequest picture;
    const ChapterInfo chapter{
        "ch12_path_guiding",
        "Chapter 12: path guiding: a spatial binary tree of directional quadtrees learned in training "
        "passes, sampled by one-sample MIS with the BSDF",
        "suite_diffuse.json",
        kRefractionChapterEffects,
        {},
        [&] {
            return guided.training_passes > 0
                       ? "each training pass learns from the passes before it, and the image from all of "
                         "them: a guided render is whole (no --samples, --resume or mpirun with several "
                         "ranks); --training-passes 0 can be split"
                       : "";
        }};
    auto flags = [&](CLI::App& app) {
        add_termination_flags(app, termination);
        add_sampler_flag(app, options.sampler);
        add_guiding_flags(app, guided, picture);
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        if (!picture.file.empty()) check_writable("--guide-picture", picture.file);
        options.termination = termination.resolved(context.scene);
        std::vector<std::string> notes = refraction_notes(context.scene, Renderer::kPaths, options);
        const auto draw = [&](const GuidingField& field, const PathTracer& tracer) {
            if (picture.file.empty()) return;
            write_png(guide_picture(field, tracer, picture, context.settings.threads), picture.file);
            notes.push_back("wrote the guide's picture " + picture.file.string());
        };
        GuidedRender run =
            render_guided(context.scene, context.simulated, context.settings, options, guided, draw);
        for (std::string& note : guiding_notes(run, guided)) notes.push_back(std::move(note));
        return ChapterRun{std::move(run.result), std::move(notes), std::nullopt};
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
