// Chapter 12: path guiding. Chapter 06's path tracer (chapter 07's materials) learns where the light comes
// from: training passes of 1, 2, 4, … samples per pixel record the radiance their paths carried into a
// spatial binary tree of directional quadtrees (Practical Path Guiding), and each vertex then draws its
// continuation from the learned distribution or the BSDF, by one-sample MIS. `--training-passes 0` renders
// chapter 06's unguided paths; the summary gives each pass's rays and the trees' memory.
#include "06_monte_carlo/sampling_flags.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "07_bsdf_refraction/refraction_notes.hpp"
#include "guided_render.hpp"
#include "rt/run/app.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    PathOptions options;
    GuidedRenderOptions guided;
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
        add_sampler_flag(app, options.sampler);
        app.add_option("--training-passes", guided.training_passes,
                       "Training passes of 1, 2, 4, ... spp before the image (0: no guiding)")
            ->check(CLI::Range(0, 16));
        app.add_option("--guided-fraction", guided.field.guided_fraction,
                       "alpha: the chance a guided vertex draws from the guide rather than the BSDF")
            ->check(CLI::Range(0.0, 0.99));
        app.add_option("--spatial-threshold", guided.field.spatial_threshold,
                       "c: a leaf of the spatial tree splits after pass k past c sqrt(2^k) vertices")
            ->check(CLI::Range(1.0, 1e9));
        app.add_option("--energy-threshold", guided.field.energy_threshold,
                       "rho: a quadrant splits past this share of its quadtree's energy")
            ->check(CLI::Range(1e-4, 0.5));
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        options.simulated = context.simulated;
        const RenderScene prepared(context.scene, context.simulated, refraction_materials());
        const PinholeCamera camera =
            make_pinhole_camera(context.scene.camera, context.settings.width, context.settings.height);
        GuidedRender run = render_guided(prepared, camera, context.settings, options, guided);
        std::vector<std::string> notes = refraction_notes(context.scene, Renderer::kPaths, options);
        for (std::string& note : guiding_notes(run, guided)) notes.push_back(std::move(note));
        return ChapterRun{std::move(run.result), std::move(notes), std::nullopt};
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
