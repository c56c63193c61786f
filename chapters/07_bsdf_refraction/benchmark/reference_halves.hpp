#pragma once
// A converged reference as two independent halves A and B, for chapter 07's benchmarks: r = (A + B) / 2, and
// its own noise is read from A − r = (A − B) / 2. Each half is rendered once and cached as a PFM.
#include <cstdint>
#include <filesystem>

#include "bsdf_render.hpp"
#include "rt/effects.hpp"
#include "rt/image_io.hpp"

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

}  // namespace rt
