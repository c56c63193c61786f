#include "shadow_study_report.hpp"

#include <cstdio>
#include <fstream>

#include "01_ray_generation/camera.hpp"
#include "analytic_scene.hpp"
#include "direct_render.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/scene_loader.hpp"

namespace rt {
namespace {

void print_study(const std::vector<ShadowStudyRow>& rows, const Scene& scene, const RenderSettings& settings,
                 const std::string& csv) {
    std::printf("shadow samples per pixel against error and time: %s, %dx%d, pixel centres, %d threads\n",
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
                << row.relative_mse << ',' << row.mean_error << ',' << row.seconds << ',' << row.shadow_rays
                << '\n';
        }
    }
}

}  // namespace

void run_shadow_study(const Scene& given, const DirectOptions& options, const RenderSettings& settings,
                      const std::string& csv) {
    if (!csv.empty()) check_writable("--csv", csv);
    const Scene scene = find_plane_under_quad(given, MaterialTable(given, options.simulated))
                            ? given
                            : load_scene(scene_path("ch04_analytic.json"));
    const MaterialTable materials(scene, options.simulated);
    const auto analytic = find_plane_under_quad(scene, materials);
    if (!analytic) throw InputError(scene.file + ": --shadow-study: not a plane under one quad light");
    const World world(scene, world_options_for(options.simulated));
    const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
    const Image exact = exact_image(*analytic, world, camera);
    const auto rows =
        shadow_study(world, materials, collect_lights(scene), options, camera, settings, exact,
                     {LightSampler::kIndependent, LightSampler::kStratified}, {1, 4, 16, 64, 256});
    print_study(rows, scene, settings, csv);
}

}  // namespace rt
