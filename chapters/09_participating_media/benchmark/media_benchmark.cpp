// What the volumetric loop costs a scene without media: chapter 09's render (its own loop on the material
// table with its media hooks) against chapter 07's (chapter 06's loop) on assets/scenes/cornell.json, run
// alternately, each time the median of the runs. Not a test: `ch09_benchmark [runs] [size] [spp]`.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "07_bsdf_refraction/bsdf_render.hpp"
#include "rt/core/effects.hpp"
#include "rt/core/median.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"
#include "volume_path_tracer.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    const int runs = argc > 1 ? std::atoi(argv[1]) : 7;
    const int size = argc > 2 ? std::atoi(argv[2]) : 200;
    const int spp = argc > 3 ? std::atoi(argv[3]) : 16;
    const Scene scene = load_scene(scene_path("cornell.json"));
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.samples_per_pixel = spp;
    settings.seed = 1;
    settings.threads = 1;
    settings.progress = ProgressStyle::kNone;
    const EffectSet ch07 = needed(scene) & EffectSet::all().without({Effect::kMedia});
    const EffectSet ch09 = needed(scene) & EffectSet::all();
    std::vector<double> t07, t09;
    double mean07 = 0, mean09 = 0;  // the two images agree: no media here
    for (int i = 0; i < runs; ++i) {
        const RenderResult a = render_with(choose_renderer(ch07), scene, ch07, settings, {});
        const RenderResult b = render_with_media(choose_renderer(ch09), scene, ch09, settings);
        t07.push_back(a.seconds);
        t09.push_back(b.seconds);
        mean07 = a.image.mean();
        mean09 = b.image.mean();
    }
    std::printf("cornell.json, %dx%d, %d spp, 1 thread, %d alternating runs each\n", size, size, spp, runs);
    std::printf("  chapter 07: median %.3f s (image mean %.6f)\n", median(t07), mean07);
    std::printf("  chapter 09: median %.3f s (image mean %.6f)\n", median(t09), mean09);
    std::printf("  ratio chapter 09 / chapter 07: %.3f\n", median(t09) / median(t07));
    return 0;
}
