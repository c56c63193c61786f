// Chapter 08: forward (light) tracing. Paths start at the lights and reach the camera through a lens
// aperture (`--variant aperture --aperture R`) or by connecting every vertex to the pinhole (`--variant
// connect`, the default); `--tracer reverse` renders the same scene with chapter 07's renderer beside it.
// `--tracer combined` adds the two: chapter 06's paths for everything but the caustics the camera sees, light
// paths for those (combined_render.hpp). `--forward-study` measures what reverse tracing saves (see
// forward_study.hpp).
#include "01_ray_generation/camera.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "07_bsdf_refraction/refraction_materials.hpp"
#include "camera_importance.hpp"
#include "combined_render.hpp"
#include "forward_flags.hpp"
#include "forward_notes.hpp"
#include "forward_study.hpp"
#include "light_tracer.hpp"
#include "rt/run/app.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    ForwardFlags forward;
    const ChapterInfo chapter{
        "ch08_forward_tracing",
        "Chapter 08: forward (light) tracing: paths from the lights, through an aperture or connected to the "
        "camera",
        "ch08_default.json",
        kForwardChapterEffects,
        {},
        [&] { return forward.renders_whole_because(); }};
    auto flags = [&](CLI::App& app) { add_forward_flags(app, forward); };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        const Scene& scene = context.scene;
        const RenderSettings& settings = context.settings;
        if (forward.study) {
            forward.study_options.threads = settings.threads;
            forward.study_options.seed = settings.seed;
            run_forward_study(forward.study_options);
            return std::nullopt;
        }
        if (forward.tracer == Tracer::kCombined) {
            const CombinedResult r = render_combined(scene, context.simulated, settings, forward.combined);
            ChapterRun run{r.render, combined_notes(scene, context.simulated, forward.combined, r),
                           std::nullopt};
            if (const std::string lens = lens_stand_in_note(scene); !lens.empty()) run.notes.push_back(lens);
            return run;
        }
        if (forward.tracer == Tracer::kReverse) {
            const Renderer renderer = choose_renderer(context.simulated);
            return ChapterRun{render_with(renderer, scene, context.simulated, settings),
                              reverse_notes(scene, context.simulated, renderer), std::nullopt};
        }
        // Light paths carry importance: the material table is built for it (chapter 07's glass scales
        // differently).
        const RenderScene prepared(scene, context.simulated, refraction_materials(Transport::kImportance));
        const PinholeCamera camera = light_tracing_camera(scene, settings.width, settings.height);
        const LightTracerOptions options = forward.light_tracer(context.simulated);
        const LightTracer tracer(prepared.world, prepared.materials, prepared.lights, camera, options);
        const SplatResult r = render_light_tracing(tracer, settings, paths_per_image(settings));
        ChapterRun run{r.render, forward_notes(prepared, options, r), std::nullopt};
        if (const std::string lens = lens_stand_in_note(scene); !lens.empty()) run.notes.push_back(lens);
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
