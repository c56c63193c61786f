#pragma once
// A converged reference as two independent halves A and B, for chapter 07's benchmarks: r = (A + B) / 2, and
// its own noise is read from A − r = (A − B) / 2. Each half is rendered once and cached as a PFM.
#include <cstdint>
#include <filesystem>
#include <string>

#include "bsdf_render.hpp"
#include "rt/io/effects.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/scene_loader.hpp"

namespace rt {

// One half: `file` if it holds an image of the settings' size, else `spp` samples with `seed` by `renderer`,
// every effect the scene needs simulated, written to `file`.
inline Image cached_half(Renderer renderer, const Scene& scene, RenderSettings settings, int spp,
                         std::uint64_t seed, const std::filesystem::path& file) {
    if (std::filesystem::exists(file)) {
        Image image = read_pfm(file);
        if (image.width() == settings.width && image.height() == settings.height) return image;
    }
    settings.samples_per_pixel = spp;
    settings.seed = seed;
    Image image = render_with(renderer, scene, needed(scene) & EffectSet::all(), settings).image;
    write_pfm(image, file);
    return image;
}

// The converged reference r = (A + B) / 2 of a scene's two cached halves at the settings' size (chapter 07's
// paths, seeds 1001 and 1002, `spp` in all, files ch07_reference_STEM_N_SPPspp_a.pfm and _b.pfm in `cache`,
// STEM the scene file's name without .json), and its own noise: the relative MSE of A against r, since
// A − r = (A − B) / 2.
struct ConvergedReference {
    Image image;
    double noise = 0;
};
inline ConvergedReference scene_reference(const Scene& scene, const std::string& stem,
                                          const RenderSettings& settings, int spp,
                                          const std::filesystem::path& cache) {
    const std::string name =
        "ch07_reference_" + stem + "_" + std::to_string(settings.width) + "_" + std::to_string(spp) + "spp";
    const Image a = cached_half(Renderer::kPaths, scene, settings, spp / 2, 1001, cache / (name + "_a.pfm"));
    const Image b = cached_half(Renderer::kPaths, scene, settings, spp / 2, 1002, cache / (name + "_b.pfm"));
    ConvergedReference r{Image(settings.width, settings.height)};
    for (std::size_t p = 0; p < r.image.pixels().size(); ++p)
        r.image.pixels()[p] = (a.pixels()[p] + b.pixels()[p]) * Real(0.5);
    r.noise = compare(a, r.image).relative_mse;
    return r;
}

// A scene of assets/scenes (the glass Cornell box, cornell.json, unless named) as chapter 07's error study
// and chapter 08's time to error measure it: every effect it needs simulated, `size`×`size` pixels on
// `threads` threads without a progress bar, and its converged reference of `reference_spp` samples from the
// cache.
struct SceneBenchmark {
    Scene scene;
    EffectSet simulated = needed(scene) & EffectSet::all();
    RenderSettings settings;
    ConvergedReference reference;
    SceneBenchmark(int size, int threads, int reference_spp, const std::filesystem::path& cache,
                   const std::string& scene_name = "cornell.json")
        : scene(load_scene(scene_path(scene_name.c_str()))) {
        settings.width = settings.height = size;
        settings.threads = threads;
        settings.progress = ProgressStyle::kNone;
        reference = scene_reference(scene, std::filesystem::path(scene_name).stem().string(), settings,
                                    reference_spp, cache);
    }
};

}  // namespace rt
