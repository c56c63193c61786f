// Chapter 04: direct lighting. Renders the direct term of the rendering equation (emission plus light
// arriving straight from area, point and environment lights, with soft shadows from N shadow rays per light)
// through four BRDFs; on the analytic scene (a plane under a quad light) it reports the error against the
// exact image, and `--shadow-study` measures shadow samples per pixel against error and time there.
#include <cstdio>
#include <fstream>
#include <string>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "analytic_scene.hpp"
#include "direct_render.hpp"
#include "rt/app.hpp"
#include "rt/assets.hpp"
#include "rt/errors.hpp"
#include "rt/image_io.hpp"
#include "rt/scene_loader.hpp"

namespace {

// "1 quad", "2 quads".
std::string count_text(std::size_t n, const std::string& what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

}  // namespace

int main(int argc, char** argv) {
    using namespace rt;
    int shadow_samples = 1;
    std::string light_sampler = "stratified";
    std::string light_selection = "auto";
    bool study = false;
    std::string csv;
    const ChapterInfo chapter{
        "ch04_direct_lighting", "Chapter 04: direct lighting, four BRDFs, area lights and soft shadows",
        "ch04_default.json", kDirectChapterEffects};
    auto flags = [&](CLI::App& app) {
        app.add_option("--shadow-samples", shadow_samples,
                       "Shadow rays per light per hit (N; soft shadows converge as N grows)")
            ->check(CLI::Range(1, 1 << 16));
        app.add_option("--light-sampler", light_sampler,
                       "How a light's N samples are spread: independent|stratified (one per cell of a grid)")
            ->check(CLI::IsMember({"independent", "stratified"}));
        app.add_option("--light-selection", light_selection,
                       "Which lights a hit samples: every (N samples each), power (N lights picked with "
                       "probability proportional to power) or auto (every light up to 16 lights, else power)")
            ->check(CLI::IsMember({"auto", "every", "power"}));
        CLI::Option* study_flag = app.add_flag(
            "--shadow-study", study,
            "On the analytic scene (default ch04_analytic.json): RMSE to the exact image and time for "
            "1, 4, 16, 64, 256 shadow samples per pixel, for both light samplers");
        app.add_option("--csv", csv, "With --shadow-study: also write the table as CSV")->check(only_with({{study_flag}}));
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        const RenderSettings& settings = context.settings;
        DirectOptions options;
        options.simulated = context.simulated;
        options.shadow_samples = shadow_samples;
        options.light_sampler = light_sampler_from_string(light_sampler);
        options.light_selection = light_selection_from_string(light_selection);
        if (study) {
            if (!csv.empty()) check_writable("--csv", csv);
            // The study needs an exact image: the given scene if it is a plane under a quad light, else the
            // course's analytic scene (at the image size of the run).
            const Scene scene =
                find_plane_under_quad(context.scene, MaterialTable(context.scene, context.simulated))
                    ? context.scene
                    : load_scene(scene_path("ch04_analytic.json"));
            const MaterialTable materials(scene, context.simulated);
            const auto analytic = find_plane_under_quad(scene, materials);
            if (!analytic)
                throw InputError(scene.file + ": --shadow-study: not a plane under one quad light");
            const World world(scene);
            const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
            const Image exact = exact_image(*analytic, world, camera);
            const auto rows =
                shadow_study(world, materials, collect_lights(scene), options, camera, settings, exact,
                             {LightSampler::kIndependent, LightSampler::kStratified}, {1, 4, 16, 64, 256});
            std::printf(
                "shadow samples per pixel against error and time: %s, %dx%d, pixel centres, %d threads\n",
                scene.file.c_str(), settings.width, settings.height, settings.threads);
            std::printf("%-12s %8s %12s %14s %12s %10s %12s\n", "sampler", "samples", "RMSE", "relative MSE",
                        "mean error", "time (s)", "shadow rays");
            std::ofstream out;
            if (!csv.empty()) {
                out.open(csv);
                out << "sampler,shadow_samples,rmse,relative_mse,mean_error,seconds,shadow_rays\n";
            }
            for (const ShadowStudyRow& row : rows) {
                std::printf("%-12s %8d %12.6f %14.3e %+12.2e %10.4f %12llu\n", to_string(row.sampler).data(),
                            row.shadow_samples, row.rmse, row.relative_mse, row.mean_error, row.seconds,
                            static_cast<unsigned long long>(row.shadow_rays));
                if (out) {
                    out << to_string(row.sampler) << ',' << row.shadow_samples << ',' << row.rmse << ','
                        << row.relative_mse << ',' << row.mean_error << ',' << row.seconds << ','
                        << row.shadow_rays << '\n';
                }
            }
            return std::nullopt;
        }

        const Scene& scene = context.scene;
        const World world(scene);
        const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
        LightSet lights = collect_lights(scene);
        const MaterialTable materials(scene, context.simulated);
        const auto analytic =
            options.simulates(Effect::kDirect) ? find_plane_under_quad(scene, materials) : std::nullopt;
        std::vector<std::string> notes = materials.notes();
        for (const std::string& u : lights.unsampled) notes.push_back("emitter not sampled as a light: " + u);
        const DirectLighting shading(world, materials, std::move(lights), options);
        const LightSet& sampled = shading.lights();
        if (sampled.empty()) {
            notes.push_back("the scene has no light to sample: no direct light, no shadow rays");
        } else {
            notes.push_back("lights: " + count_text(sampled.quads.size(), "quad") + ", " +
                            count_text(sampled.triangles.size(), "triangle") + ", " +
                            count_text(sampled.spheres.size(), "sphere") + ", " +
                            count_text(sampled.points.size(), "point") +
                            (sampled.environment ? ", an environment" : "") + "; " +
                            count_text(std::size_t(shadow_samples), "shadow sample") +
                            (shading.picks_lights() ? " per hit, each from a light picked by power, "
                                                    : " per light per hit, ") +
                            light_sampler);
        }
        ChapterRun run{render_direct(shading, camera, settings,
                                     analytic ? FilmPoints::kCentre : FilmPoints::kStratified),
                       std::move(notes), std::nullopt};
        if (analytic) {
            run.exact = exact_image(*analytic, world, camera);
            run.notes.push_back(
                "analytic scene (a diffuse plane under one quad light): rays through pixel centres, compared "
                "with "
                "rho/pi * E from Lambert's polygon formula");
        }
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
