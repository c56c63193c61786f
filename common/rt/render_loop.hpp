// The parallel render loop: every pixel gets `spp` samples; tiles of 16×16 pixels are handed to the threads.
// Samples are taken in passes (all pixels get samples [a, b) before any gets sample b), so an interrupted
// render still has an even image. An interrupt is looked for before every sample, so a render stops within
// one sample per thread, however slow a sample is; the pass of a tile it cuts short is dropped, so every
// pixel keeps the mean of whole passes. Each sample gets its own random stream from (pixel, sample, seed) and a
// pixel's samples are summed in order, so the image is bit-identical for any number of threads.
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "rt/image.hpp"
#include "rt/random.hpp"
#include "rt/ray_counts.hpp"

namespace rt {

enum class ProgressStyle { kAuto, kBar, kLines, kNone };

struct RenderSettings {
    int width = 0;
    int height = 0;
    int samples_per_pixel = 1;
    std::uint64_t seed = 0;
    int threads = 0;  // 0: every core
    ProgressStyle progress = ProgressStyle::kAuto;
};

// Pixels x in [x0, x1), y in [y0, y1).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct RenderResult {
    Image image;
    RayCounts rays;
    double seconds = 0;
    std::uint64_t samples = 0;     // samples actually taken (and kept)
    int samples_per_pixel = 0;     // samples every pixel has (less than asked when interrupted)
    bool interrupted = false;
    // Interrupted in the first pass: the pixels left without a sample (black), and the rectangle holding them.
    std::uint64_t unsampled_pixels = 0;
    PixelRect unsampled_region;
};

// Where one sample is taken: pixel (x, y), sample number `index` of that pixel.
struct PixelSample {
    int x;
    int y;
    int index;
};

// One sample's radiance. Counts the rays it traces into `rays` (the calling thread's own counter).
template <typename F>
concept SampleFunction = requires(F f, const PixelSample& s, Pcg32& rng, RayCounts& rays) {
    { f(s, rng, rays) } -> std::convertible_to<Color>;
};

namespace detail {
inline constexpr int kTileSize = 16;
// Runs `render_tile(x0, y0, x1, y1, first_sample, end_sample, rays)` over every tile and pass; it returns
// false when an interrupt cut the tile's pass short (and then left `sums` as they were). If it throws on any
// thread, the other threads stop after their tile and the first exception is rethrown here.
using TileFunction = std::function<bool(int, int, int, int, int, int, RayCounts&)>;
RenderResult render_tiles(const RenderSettings& settings, Image& sums, const TileFunction& render_tile);
bool interrupted();  // interrupt_requested(), without interrupt.hpp in every chapter
}  // namespace detail

template <SampleFunction F>
RenderResult render(const RenderSettings& settings, F&& sample) {
    Image sums(settings.width, settings.height);
    const std::uint64_t width = std::uint64_t(settings.width);
    return detail::render_tiles(
        settings, sums, [&](int x0, int y0, int x1, int y1, int first, int end, RayCounts& rays) {
            // The pass is summed aside and kept only once whole.
            std::array<Color, std::size_t(detail::kTileSize * detail::kTileSize)> tile;
            for (int y = y0; y < y1; ++y) {
                for (int x = x0; x < x1; ++x) {
                    const std::uint64_t pixel = std::uint64_t(y) * width + std::uint64_t(x);
                    Color sum = sums.at(x, y);
                    for (int s = first; s < end; ++s) {
                        if (detail::interrupted()) return false;
                        Pcg32 rng = Pcg32::for_sample(pixel, std::uint64_t(s), settings.seed);
                        sum += Color(sample(PixelSample{x, y, s}, rng, rays));
                    }
                    tile[std::size_t((y - y0) * detail::kTileSize + (x - x0))] = sum;
                }
            }
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) sums.at(x, y) = tile[std::size_t((y - y0) * detail::kTileSize + (x - x0))];
            return true;
        });
}

}  // namespace rt
