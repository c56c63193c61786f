#include "splat_render.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

#include "rt/render/interrupt.hpp"
#include "rt/render/parallel_for.hpp"

namespace rt {
namespace {

// Chunks traced between two merges: a fixed number, so the memory for chunk films stays bounded.
constexpr std::uint64_t kChunksPerWave = 8;
// Paths between two looks at the interrupt flag.
constexpr std::uint64_t kInterruptCheck = 1024;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct ChunkTraced {
    std::uint64_t contributing = 0;  // paths that added to the film
    bool complete = false;           // false: an interrupt cut it short
};

// Traces paths [first, end) into `film` (zeroed first), each from its own stream; gives up within
// kInterruptCheck paths of an interrupt.
ChunkTraced trace_chunk(std::uint64_t first, std::uint64_t end, std::uint64_t seed,
                        const LightPathFunction& trace, Image& film, RayCounts& rays) {
    std::fill(film.pixels().begin(), film.pixels().end(), Color(0));
    ChunkTraced out;
    bool stopped = false;
    for (std::uint64_t i = first; i < end && !stopped; ++i) {
        Pcg32 rng = Pcg32::for_sample(i, 0, seed);
        if (trace(i, rng, film, rays)) ++out.contributing;
        // Ctrl-C: give up this chunk (it is not merged) within a few thousand paths.
        stopped = (i - first) % kInterruptCheck == kInterruptCheck - 1 && interrupt_requested();
    }
    out.complete = !stopped;
    return out;
}

}  // namespace

std::uint64_t chunk_size(int width, int height) {
    return std::max<std::uint64_t>(1u << 14, std::uint64_t(width) * std::uint64_t(height));
}

SplatResult render_light_paths(const RenderSettings& settings, std::uint64_t path_count,
                               const LightPathFunction& trace) {
    const auto start = std::chrono::steady_clock::now();
    const int threads = thread_count(settings.threads);
    const std::uint64_t chunk = chunk_size(settings.width, settings.height);
    const std::uint64_t chunk_count = (path_count + chunk - 1) / chunk;
    const std::size_t pixels = std::size_t(settings.width) * std::size_t(settings.height);

    std::vector<Vec3d> sums(pixels, Vec3d(0));
    std::vector<Image> films;
    for (std::uint64_t c = 0; c < std::min(kChunksPerWave, chunk_count); ++c)
        films.emplace_back(settings.width, settings.height);
    std::vector<std::uint64_t> contributing(films.size(), 0);
    std::vector<std::uint8_t> complete(films.size(), 0);
    std::vector<ThreadRayCounts> rays_per_thread(static_cast<std::size_t>(threads));
    std::uint64_t traced = 0, contributed = 0;
    bool interrupted = false;
    // I = (1 / N) Σ_paths (their splats), over the N paths traced so far.
    auto image_so_far = [&] {
        Image image(settings.width, settings.height);
        const double scale = traced > 0 ? 1.0 / double(traced) : 0.0;
        for (std::size_t p = 0; p < pixels; ++p) image.pixels()[p] = Color(sums[p] * scale);
        return image;
    };
    auto rays_so_far = [&] {
        RayCounts rays;
        for (const RayCounts& c : rays_per_thread) rays += c;
        return rays;
    };

    for (std::uint64_t wave = 0; wave < chunk_count; wave += kChunksPerWave) {
        if (interrupt_requested()) {
            interrupted = true;
            break;
        }
        const std::uint64_t wave_chunks = std::min(kChunksPerWave, chunk_count - wave);
        std::fill(complete.begin(), complete.end(), std::uint8_t(0));
        // A chunk not started (the engine stops handing them out at an interrupt) stays incomplete.
        parallel_for(wave_chunks, {.threads = threads, .stop = interrupt_requested},
                     [&](std::size_t c, int thread) {
                         const std::uint64_t first = (wave + c) * chunk;
                         const ChunkTraced traced_chunk =
                             trace_chunk(first, std::min(path_count, first + chunk), settings.seed, trace,
                                         films[c], rays_per_thread[std::size_t(thread)]);
                         contributing[c] = traced_chunk.contributing;
                         complete[c] = traced_chunk.complete ? 1 : 0;
                     });
        // The merge, in chunk order: the same sums whatever thread traced which chunk. When interrupted, only
        // the chunks before the first incomplete one, so the image averages paths 0 … traced − 1.
        for (std::uint64_t c = 0; c < wave_chunks; ++c) {
            if (!complete[c]) {
                interrupted = true;
                break;
            }
            const std::vector<Color>& film = films[c].pixels();
            for (std::size_t p = 0; p < pixels; ++p) sums[p] += Vec3d(film[p]);
            contributed += contributing[c];
            traced += std::min(path_count, (wave + c + 1) * chunk) - (wave + c) * chunk;
        }
        if (interrupted) break;
        if (settings.observer && !interrupt_requested()) {
            const Image image = image_so_far();
            settings.observer->after_pass(PassReport{image, std::uint32_t(traced / pixels), traced,
                                                     rays_so_far(), traced, seconds_since(start)});
        }
    }

    SplatResult out;
    out.contributing_paths = contributed;
    RenderResult& r = out.render;
    r.image = image_so_far();
    r.rays = rays_so_far();
    r.samples = traced;
    r.samples_per_pixel = int(traced / std::max<std::uint64_t>(1, pixels));
    r.interrupted = interrupted;
    r.seconds = seconds_since(start);
    return out;
}

}  // namespace rt
