// Chapter 03: shadow rays. Point lights light diffuse surfaces (point_light.hpp) wherever a
// shadow ray reaches them; `--offset none|epsilon|robust` chooses how a shadow ray leaves the surface, and
// `--offset-study` measures what each method costs and gets wrong at scales from 1e-3 to 1e5.
#include <string>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "offset_study_report.hpp"
#include "ray_offset.hpp"
#include "rt/flags/enum_flag.hpp"
#include "rt/flags/study_flags.hpp"
#include "rt/run/app.hpp"
#include "scene_scale.hpp"
#include "shadow_notes.hpp"
#include "shadow_render.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    OffsetMethod method = OffsetMethod::kRobust;
    Real epsilon = Real(1e-4);
    Real scale = 1;
    bool study = false;
    OffsetStudyRequest study_request;
    const ChapterInfo chapter{"ch03_shadow_rays", "Chapter 03: point lights, shadow rays and ray offsets",
                              "ch03_default.json", kShadowChapterEffects};
    auto flags = [&](CLI::App& app) {
        CLI::Option* offset_flag = add_enum_option(
            app, method, "How a shadow ray leaves its surface: " + joined_names<OffsetMethod>());
        app.add_option(
            "--scale", scale,
            "Multiply every length of the scene by this, in [1e-12, 1e12] (intensities by its square)");
        CLI::Option* study_flag = app.add_flag(
            "--offset-study", study,
            "Count self-hits, acne and leak pixels and time each offset at each of --study-scales");
        app.add_option("--epsilon", epsilon,
                       "The fixed distance of --offset epsilon and of the study's (default 1e-4)")
            ->check(only_with({{offset_flag, {"epsilon"}}, {study_flag}}));
        app.add_option("--study-scales", study_request.scales,
                       "With --offset-study: the scales (default 1e-3 1 1e3 1e5)")
            ->check(only_with({{study_flag}}));
        add_study_option(app, kCsvOption, study_request.csv, {{study_flag}});
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        const RayOffset offset = make_ray_offset(method, epsilon);
        const RenderSettings& settings = context.settings;
        if (study) {
            run_offset_study(context.scene, study_request, scale, epsilon, settings);
            return std::nullopt;
        }
        const Scene scene = scale_scene(context.scene, scale);
        const World world(scene);
        const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
        const RenderResult result =
            render_shadows(world, scene, camera, shadow_options(context.simulated, offset), settings);
        return ChapterRun{result, shadow_notes(scene, offset, scale, result), std::nullopt};
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
