// Chapter 01: ray generation. Renders each camera ray's direction as a colour over a sky gradient, split by
// a straight edge; `--aa-study` measures what anti-aliasing costs against the edge's exact coverage.
#include "camera.hpp"
#include "edge_coverage.hpp"
#include "ray_generation_render.hpp"
#include "rt/flags/enum_flag.hpp"
#include "rt/flags/study_flags.hpp"
#include "rt/run/app.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    PixelSampler sampler = PixelSampler::kStratified;
    Real tilt_degrees = 20;
    bool study = false;
    std::string csv;
    const ChapterInfo chapter{"ch01_ray_generation", "Chapter 01: ray generation with a pinhole camera",
                              "ch01_default.json", EffectSet{Effect::kCameraRays}};
    auto flags = [&](CLI::App& app) {
        add_enum_option(app, sampler, "Where samples fall in a pixel: " + joined_names<PixelSampler>());
        app.add_option("--edge-tilt", tilt_degrees, "Tilt of the edge from the vertical, degrees");
        CLI::Option* study_flag = app.add_flag(
            "--aa-study", study, "Measure edge error against time for each sampler and 1..256 spp");
        add_study_option(app, kCsvOption, csv, {{study_flag}});
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        const RenderSettings& settings = context.settings;
        const PinholeCamera camera =
            make_pinhole_camera(context.scene.camera, settings.width, settings.height);
        const FilmEdge edge = make_film_edge(camera, tilt_degrees);
        if (!study) {
            ChapterRun run{render_directions(camera, edge, sampler, settings), {}, std::nullopt};
            run.notes.push_back(std::string("pixel sampler: ") + std::string(to_string(sampler)));
            if (!context.scene.shapes.empty()) {
                run.notes.push_back(
                    "the scene's shapes are not intersected before chapter 02; rays show directions");
            }
            return run;
        }
        run_antialiasing_study(camera, edge, settings, csv);
        return std::nullopt;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
