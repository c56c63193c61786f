// What depth of field costs in samples (not a test): `ch02_lens_study` prints the table of chapter 01's
// lesson. The thin-lens scene (ch01_thin_lens.json, chapter 02's normal colours) is rendered at a few
// apertures: for each, a reference of --reference spp, then 1, 4, 16, 64 and 256 spp (seeds apart from the
// reference's), each timed, with its RMSE against the reference. A pinhole (aperture 0) needs samples only
// for the pixels' edges; a lens needs them for every pixel whose disk of confusion covers more than one
// colour.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <string>

#include "01_ray_generation/camera.hpp"
#include "intersection_render.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/run/strict_flags.hpp"
#include "world.hpp"

namespace {

using namespace rt;

double rmse(const Image& a, const Image& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.pixel_count(); ++i) {
        const Color d = a.pixels()[i] - b.pixels()[i];
        sum += double(glm::dot(d, d)) / 3;
    }
    return std::sqrt(sum / double(a.pixel_count()));
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"ch02_lens_study: RMSE against a reference and time, by aperture and samples per pixel"};
    int reference_spp = 4096;
    int threads = 0;
    app.add_option("--reference", reference_spp, "Samples per pixel of each aperture's reference")
        ->check(CLI::Range(1, 1 << 20));
    app.add_option("--threads", threads, "Threads (0: every core)")->check(CLI::Range(0, 1024));
    if (const auto stop = rt::read_flags(app, argc, argv)) return *stop;

    Scene scene = load_scene(scene_path("ch01_thin_lens.json"));
    const World world(scene, WorldOptions{});
    RenderSettings settings;
    settings.width = scene.image.width;
    settings.height = scene.image.height;
    settings.threads = threads;
    settings.progress = ProgressStyle::kNone;
    const Real scale = glm::length(scene.camera.at - scene.camera.from) / 2;
    std::printf("thin lens, %s (%dx%d, focus %.3g), normal colours; RMSE against %d spp\n",
                scene.file.c_str(), settings.width, settings.height, double(*scene.camera.focus_distance),
                reference_spp);
    std::printf("%-9s %5s %10s %10s\n", "aperture", "spp", "RMSE", "time (s)");
    for (Real aperture : {0.0f, 0.03f, 0.12f, 0.48f}) {
        scene.camera.aperture = aperture;
        const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
        RenderSettings reference = settings;
        reference.samples_per_pixel = reference_spp;
        reference.seed = 1000;
        const Image truth = render_intersections(world, camera, ShowMode::kNormal, scale, reference).image;
        for (int spp : {1, 4, 16, 64, 256}) {
            settings.samples_per_pixel = spp;
            const RenderResult r = render_intersections(world, camera, ShowMode::kNormal, scale, settings);
            std::printf("%-9.3g %5d %10.5f %10.4f\n", double(aperture), spp, rmse(r.image, truth), r.seconds);
        }
    }
    return 0;
}
