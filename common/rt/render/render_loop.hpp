// The parallel render loop: every pixel gets `spp` samples; tiles of 16×16 pixels are handed to the threads.
// Samples are taken in passes (all pixels get samples [a, b) before any gets sample b), so an interrupted
// render still has an even image. An interrupt is looked for before every sample, so a render stops within
// one sample per thread, however slow a sample is; the pass of a tile it cuts short is dropped, so every
// pixel keeps whole passes. Each sample gets its own random stream from (pixel, sample, seed) and a pixel's
// samples are summed exactly (pixel_sums.hpp), so the image is bit-identical for any number of threads, and
// for a render taken in pieces of its samples (settings.samples) or continued (settings.resume).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <utility>

#include "rt/core/image.hpp"
#include "rt/core/pixel_sums.hpp"
#include "rt/core/random.hpp"
#include "rt/core/ray_counts.hpp"
#include "rt/core/sample_range.hpp"
#include "rt/render/render_observer.hpp"

namespace rt {

enum class ProgressStyle { kAuto, kBar, kLines, kNone };

struct RenderSettings {
    int width = 0;
    int height = 0;
    int samples_per_pixel = 1;  // of the whole render: a sample function may depend on it (strata)
    std::uint64_t seed = 0;
    int threads = 0;  // 0: every core
    ProgressStyle progress = ProgressStyle::kAuto;
    // The samples this run takes (--samples A:B, or one MPI rank's share); all of them when empty.
    std::optional<SampleRange> samples = std::nullopt;
    // Sums to continue (--resume; not owned): pixel p already holds samples first … first + count − 1 of
    // `samples`, and the render takes the rest.
    const PixelSums* resume = nullptr;
    // What watches the render (not owned; render_observer.hpp): the app's heat maps, the live view. None:
    // nothing is measured.
    RenderObserver* observer = nullptr;
    // Work the render does before each pass, told the end of the pass's samples (chapter 08's combined
    // tracer traces there the light paths of the camera samples the image will then have). None by default.
    std::function<void(int end)> before_pass = nullptr;
};

// The samples a render with these settings takes.
inline SampleRange samples_taken(const RenderSettings& settings) {
    return settings.samples.value_or(SampleRange{0, std::max(settings.samples_per_pixel, 1)});
}

// The samples of each pass after the first (which takes one per pixel) for a render of `samples` samples:
// ⌈samples / 8⌉, at most 16.
int pass_samples(int samples);

struct RenderResult {
    Image image;     // each pixel the mean of its samples in `sums`
    PixelSums sums;  // empty for a render that splats (chapter 08's light paths) instead of sampling pixels
    RayCounts rays;
    double seconds = 0;
    std::uint64_t samples = 0;  // samples actually taken (and kept)
    int samples_per_pixel = 0;  // samples every pixel has (fewer than asked when interrupted)
    bool interrupted = false;
    // Interrupted in the first pass: the pixels left without a sample (black), and the rectangle holding
    // them.
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
// Runs `render_tile(x0, y0, x1, y1, first_sample, end_sample, rays)` over every tile and pass, adding into
// `sums` (the resumed sums, or zeros), which the result then takes; it returns false when an interrupt cut
// the tile's pass short (and then left `sums` as they were). If it throws on any thread, the other threads
// stop after their tile and the first exception is rethrown here.
using TileFunction = std::function<bool(int, int, int, int, int, int, RayCounts&)>;
RenderResult render_tiles(const RenderSettings& settings, PixelSums& sums, const TileFunction& render_tile);
// The sums a render starts from: settings.resume's, or zeros. Throws std::logic_error on a size mismatch.
PixelSums starting_sums(const RenderSettings& settings);
bool interrupted();  // interrupt_requested(), without interrupt.hpp in every chapter
}  // namespace detail

// A sample that gives more than the image: layer 0 is its colour, the layers after it are summed beside the
// image, each exactly into its own PixelSums (chapter 10's feature buffers and squared colours).
template <typename F, std::size_t Layers>
concept LayeredSampleFunction = requires(F f, const PixelSample& s, Pcg32& rng, RayCounts& rays) {
    { f(s, rng, rays) } -> std::convertible_to<std::array<Color, Layers>>;
};

// render() with `Extra` layers beside the image: sample() returns 1 + Extra colours, and layer k + 1 is
// summed into extra[k] (resized to the image), with the same passes, interrupts and dropped partial passes as
// the image. A render with layers takes all its samples from zero: settings.resume must be empty.
template <std::size_t Extra, LayeredSampleFunction<1 + Extra> F>
RenderResult render_layers(const RenderSettings& settings, std::array<PixelSums, Extra>& extra, F&& sample) {
    PixelSums sums = detail::starting_sums(settings);
    if constexpr (Extra > 0) {
        if (settings.resume) throw std::logic_error("render_layers: a render with layers cannot be resumed");
        for (PixelSums& layer : extra) layer = PixelSums(settings.width, settings.height);
    }
    const int range_first = samples_taken(settings).first;
    const std::uint64_t width = std::uint64_t(settings.width);
    const bool measures_cost = settings.observer && settings.observer->measures_cost();
    return detail::render_tiles(
        settings, sums, [&](int x0, int y0, int x1, int y1, int first, int end, RayCounts& rays) {
            // The pass is summed aside and kept only once whole.
            constexpr std::size_t kTilePixels = std::size_t(detail::kTileSize * detail::kTileSize);
            std::array<PixelSum, kTilePixels> tile;
            std::array<std::array<PixelSum, Extra>, kTilePixels> tile_extra;
            std::array<PixelCost, kTilePixels> cost{};
            for (int y = y0; y < y1; ++y) {
                for (int x = x0; x < x1; ++x) {
                    const std::uint64_t pixel = std::uint64_t(y) * width + std::uint64_t(x);
                    const std::size_t slot = std::size_t((y - y0) * detail::kTileSize + (x - x0));
                    PixelSum sum = sums.at(x, y);
                    std::array<PixelSum, Extra>& layers = tile_extra[slot];
                    for (std::size_t k = 0; k < Extra; ++k) layers[k] = extra[k].at(x, y);
                    const RayCounts before = rays;
                    const std::uint64_t count_before = sum.count;
                    for (int s = std::max(first, range_first + int(sum.count)); s < end; ++s) {
                        if (detail::interrupted()) return false;
                        Pcg32 rng = Pcg32::for_sample(pixel, std::uint64_t(s), settings.seed);
                        const std::array<Color, 1 + Extra> values = sample(PixelSample{x, y, s}, rng, rays);
                        sum.add(values[0]);
                        for (std::size_t k = 0; k < Extra; ++k) layers[k].add(values[k + 1]);
                    }
                    if (measures_cost) {
                        auto traced = [&](RayKind k) { return rays[k] - before[k]; };
                        cost[slot] = {rays.total() - before.total(),
                                      traced(RayKind::kReflection) + traced(RayKind::kRefraction) +
                                          traced(RayKind::kIndirect),
                                      std::uint64_t(sum.count - count_before)};
                    }
                    tile[slot] = std::move(sum);
                }
            }
            for (int y = y0; y < y1; ++y) {
                for (int x = x0; x < x1; ++x) {
                    const std::size_t slot = std::size_t((y - y0) * detail::kTileSize + (x - x0));
                    sums.at(x, y) = std::move(tile[slot]);
                    for (std::size_t k = 0; k < Extra; ++k) extra[k].at(x, y) = std::move(tile_extra[slot][k]);
                    if (measures_cost) settings.observer->add_cost(x, y, cost[slot]);
                }
            }
            return true;
        });
}

template <SampleFunction F>
RenderResult render(const RenderSettings& settings, F&& sample) {
    std::array<PixelSums, 0> no_layers;
    return render_layers(settings, no_layers, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        return std::array<Color, 1>{Color(sample(s, rng, rays))};
    });
}

}  // namespace rt
