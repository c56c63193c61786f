// Chapter 04: direct lighting. Renders the direct term of the rendering equation (emission plus light
// arriving straight from area, point and environment lights, with soft shadows from N shadow rays per light)
// through four BRDFs; on the analytic scene (a plane under a quad light) it reports the error against the
// exact image, and `--shadow-study` measures shadow samples per pixel against error and time there.
#include <string>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "analytic_scene.hpp"
#include "direct_notes.hpp"
#include "direct_render.hpp"
#include "quad_lights_flag.hpp"
#include "rt/flags/enum_flag.hpp"
#include "rt/flags/study_flags.hpp"
#include "rt/run/app.hpp"
#include "shadow_study_report.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    DirectOptions options;
    ShadingNormalFix shading_normals = ShadingNormalFix::kBend;
    bool study = false;
    std::string csv;
    const ChapterInfo chapter{"ch04_direct_lighting",
                              "Chapter 04: direct lighting, four BRDFs, area lights and soft shadows",
                              "ch04_default.json", kDirectChapterEffects};
    auto flags = [&](CLI::App& app) {
        app.add_option("--shadow-samples", options.shadow_samples,
                       "Shadow rays per light per hit (N; soft shadows converge as N grows)")
            ->check(CLI::Range(1, 1 << 16));
        add_enum_option(
            app, options.light_sampler,
            "How a light's N samples are spread: independent|stratified (one per cell of a grid)");
        add_enum_option(
            app, options.light_selection,
            "Which lights a hit samples: every (N samples each), power (N lights picked with "
            "probability proportional to power) or auto (every light up to 16 lights, else power)");
        add_quad_lights_flag(app, options.quad_lights);
        add_enum_option(app, shading_normals,
                        "A smooth mesh's shading normals: bend (the fix), raw (interpolated only) or flat "
                        "(faceted)");
        CLI::Option* study_flag = app.add_flag(
            "--shadow-study", study,
            "On the analytic scene (default ch04_analytic.json): RMSE to the exact image and time for "
            "1, 4, 16, 64, 256 shadow samples per pixel, for both light samplers");
        add_study_option(app, kCsvOption, csv, {{study_flag}});
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        const RenderSettings& settings = context.settings;
        options.simulated = context.simulated;
        if (study) {
            run_shadow_study(context.scene, options, settings, csv);
            return std::nullopt;
        }
        const Scene& scene = context.scene;
        const World world(scene, world_options_for(context.simulated, shading_normals));
        const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
        const MaterialTable materials(scene, context.simulated);
        const auto analytic =
            options.simulates(Effect::kDirect) ? find_plane_under_quad(scene, materials) : std::nullopt;
        const DirectLighting shading(world, materials, collect_lights(scene), options);
        ChapterRun run{render_direct(shading, camera, settings,
                                     analytic ? FilmPoints::kCentre : FilmPoints::kStratified),
                       direct_notes(materials, shading, options, analytic.has_value()), std::nullopt};
        if (analytic) run.exact = exact_image(*analytic, world, camera);
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
