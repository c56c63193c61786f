// What media cost a scene without them, on assets/scenes/cornell.json: chapter 07's render, chapter 09's
// (which hands a run without media to chapter 07's loop), and chapter 09's volumetric loop forced onto the
// scene (what the hand-over saves), in turn, the order rotated each run; medians of the times, and of each
// run's ratios to chapter 07 (the renders of a run are close in time, so the machine's drift cancels).
// Not a test: `ch09_benchmark [runs] [size] [spp]`.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "media_materials.hpp"
#include "rt/core/median.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/run/strict_flags.hpp"
#include "volume_path_tracer.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    int runs = 7, size = 200, spp = 16;
    CLI::App app("ch09_benchmark: what media cost a scene without them (cornell.json)");
    app.option_defaults()->always_capture_default();
    app.add_option("runs", runs, "Alternating runs of each render")->check(CLI::Range(1, 99));
    app.add_option("size", size, "Image width and height")->check(CLI::Range(1, 4096));
    app.add_option("spp", spp, "Samples per pixel")->check(CLI::Range(1, 1 << 20));
    if (const auto stop = read_flags(app, argc, argv)) return *stop;
    const Scene scene = load_scene(scene_path("cornell.json"));
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.samples_per_pixel = spp;
    settings.seed = 1;
    settings.threads = 1;
    settings.progress = ProgressStyle::kNone;
    const EffectSet ch07 = needed(scene) & EffectSet::all().without({Effect::kMedia});
    const EffectSet ch09 = needed(scene) & EffectSet::all();
    const RenderScene prepared(scene, ch09, media_materials());
    PathOptions options;
    options.simulated = ch09;
    const VolumePathTracer volumetric(prepared.world, prepared.materials, prepared.lights, options);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
    const char* names[] = {"chapter 07", "chapter 09", "chapter 09's volumetric loop"};
    std::vector<double> seconds[3], ratios[3];
    double means[3] = {0, 0, 0};  // the three images agree: no media here
    const auto render = [&](int k) {
        if (k == 0) return render_with(choose_renderer(ch07), scene, ch07, settings, {});
        if (k == 1) return render_with_media(choose_renderer(ch09), scene, ch09, settings);
        return render_paths(volumetric, camera, settings);
    };
    for (int i = 0; i < runs; ++i) {
        for (int j = 0; j < 3; ++j) {  // the order turns each run: none always goes first
            const int k = (i + j) % 3;
            const RenderResult r = render(k);
            seconds[k].push_back(r.seconds);
            means[k] = r.image.mean();
        }
        for (int k = 0; k < 3; ++k) ratios[k].push_back(seconds[k].back() / seconds[0].back());
    }
    std::printf("cornell.json, %dx%d, %d spp, 1 thread, %d alternating runs each\n", size, size, spp, runs);
    for (int k = 0; k < 3; ++k)
        std::printf("  %-29s median %.3f s (image mean %.6f), ratio to chapter 07 %.3f\n", names[k],
                    median(seconds[k]), means[k], median(ratios[k]));
    return 0;
}
