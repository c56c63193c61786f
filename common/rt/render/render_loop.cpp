#include "rt/render/render_loop.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <vector>

#include "rt/render/interrupt.hpp"
#include "rt/render/parallel_for.hpp"
#include "rt/render/progress.hpp"

namespace rt {

// Samples are taken in passes: first one sample per pixel (so an image interrupted after it covers every
// pixel), then an eighth of the rest per pass, but at most kMaxPassSamples, so that the passes a tile keeps
// stay even. An interrupt is answered within a sample (render_loop.hpp), whatever the pass.
int pass_samples(int samples) {
    constexpr int kPasses = 8;
    constexpr int kMaxPassSamples = 16;
    return std::clamp((samples + kPasses - 1) / kPasses, 1, kMaxPassSamples);
}

}  // namespace rt

namespace rt::detail {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

PixelSums starting_sums(const RenderSettings& settings) {
    if (!settings.resume) return PixelSums(settings.width, settings.height);
    if (settings.resume->width() != settings.width || settings.resume->height() != settings.height)
        throw std::logic_error("render: the sums to resume are not the size of the image");
    return *settings.resume;
}

RenderResult render_tiles(const RenderSettings& settings, PixelSums& sums, const TileFunction& render_tile) {
    const SampleRange range = samples_taken(settings);
    const int threads = thread_count(settings.threads);
    Progress progress(settings.progress);

    const int tiles_x = (settings.width + kTileSize - 1) / kTileSize;
    const int tiles_y = (settings.height + kTileSize - 1) / kTileSize;
    const int tile_count = tiles_x * tiles_y;
    const double total_samples = double(settings.width) * double(settings.height) * range.size();
    auto tile_bounds = [&](int tile) {
        const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
        return std::array<int, 4>{x0, y0, std::min(x0 + kTileSize, settings.width),
                                  std::min(y0 + kTileSize, settings.height)};
    };
    // Samples a tile's pixels have before `end` of a pass: those resumed count as taken.
    auto samples_in = [&](int x0, int y0, int x1, int y1, int first, int end) {
        std::uint64_t n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                const int from = std::max(first, range.first + int(sums.at(x, y).count));
                n += std::uint64_t(std::max(0, end - from));
            }
        return n;
    };

    std::vector<ThreadRayCounts> rays_per_thread(static_cast<std::size_t>(threads));
    const std::uint64_t samples_resumed = sums.total_count();
    std::atomic<std::uint64_t> samples_done{0};  // by this run
    const auto start = Clock::now();

    const int per_pass = pass_samples(range.size());
    for (int first = range.first, end = range.first + 1; first < range.end && !interrupt_requested();
         first = end, end = std::min(range.end, end + per_pass)) {
        if (settings.before_pass) settings.before_pass(end);
        auto fraction_done = [&] { return double(samples_resumed + samples_done.load()) / total_samples; };
        ParallelOptions options{.threads = threads, .stop = interrupt_requested};
        if (progress.animated())
            options.show_progress = [&] { progress.show(fraction_done(), seconds_since(start)); };
        parallel_for(std::size_t(tile_count), options, [&](std::size_t tile, int thread) {
            const auto [x0, y0, x1, y1] = tile_bounds(int(tile));
            const std::uint64_t taken = samples_in(x0, y0, x1, y1, first, end);
            if (taken == 0) return;
            // A pass cut short by an interrupt is dropped; the engine then starts no further tile.
            if (render_tile(x0, y0, x1, y1, first, end, rays_per_thread[std::size_t(thread)]))
                samples_done += taken;
        });
        progress.show(fraction_done(), seconds_since(start));
        if (settings.observer && !interrupt_requested()) {
            RayCounts rays;
            for (const RayCounts& r : rays_per_thread) rays += r;
            const Image image = sums.mean_image();
            settings.observer->after_pass(PassReport{image, sums.min_count(), sums.total_count(), rays,
                                                     samples_done.load(), seconds_since(start)});
        }
    }
    progress.clear();

    RenderResult result;
    result.seconds = seconds_since(start);
    for (const RayCounts& r : rays_per_thread) result.rays += r;
    // Each pixel is the mean of the samples it has; after an interrupt, tiles may differ by one pass.
    result.samples_per_pixel = int(sums.min_count());
    // Interrupted in the first pass: the pixels without a sample, and the rectangle that holds them.
    PixelRect& unsampled = result.unsampled_region;
    unsampled = {settings.width, settings.height, 0, 0};
    for (int y = 0; y < settings.height; ++y) {
        for (int x = 0; x < settings.width; ++x) {
            if (sums.at(x, y).count > 0) continue;
            ++result.unsampled_pixels;
            unsampled = {std::min(unsampled.x0, x), std::min(unsampled.y0, y), std::max(unsampled.x1, x + 1),
                         std::max(unsampled.y1, y + 1)};
        }
    }
    if (result.unsampled_pixels == 0) unsampled = {};
    result.samples = samples_done.load();
    result.interrupted = result.samples_per_pixel < range.size();
    result.image = sums.mean_image();
    result.sums = std::move(sums);
    return result;
}

bool interrupted() {
    return interrupt_requested();
}

}  // namespace rt::detail
