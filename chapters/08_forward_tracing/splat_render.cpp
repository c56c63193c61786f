#include "splat_render.hpp"

#include <algorithm>
#include <chrono>
#include <utility>
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
    SplatRender render(settings, path_count, trace);
    render.trace_until(path_count);
    return render.result();
}

SplatRender::SplatRender(const RenderSettings& settings, std::uint64_t path_count, LightPathFunction trace)
    : settings_(settings),
      path_count_(path_count),
      trace_(std::move(trace)),
      threads_(thread_count(settings.threads)),
      chunk_(chunk_size(settings.width, settings.height)),
      chunk_count_((path_count + chunk_ - 1) / chunk_),
      pixels_(std::size_t(settings.width) * std::size_t(settings.height)),
      sums_(pixels_, Vec3d(0)),
      rays_per_thread_(static_cast<std::size_t>(threads_)) {
    for (std::uint64_t c = 0; c < std::min(kChunksPerWave, chunk_count_); ++c)
        films_.emplace_back(settings.width, settings.height);
    contributing_.assign(films_.size(), 0);
    complete_.assign(films_.size(), 0);
}

void SplatRender::trace_until(std::uint64_t paths) {
    const auto start = std::chrono::steady_clock::now();
    while (next_wave_ < chunk_count_ && traced_ < std::min(paths, path_count_) && !interrupted_) {
        if (interrupt_requested()) {
            interrupted_ = true;
            break;
        }
        trace_wave();
        if (!interrupted_ && settings_.observer && !interrupt_requested()) {
            const Image image = image_so_far();
            settings_.observer->after_pass(PassReport{image, std::uint32_t(traced_ / pixels_), traced_,
                                                      rays_so_far(), traced_,
                                                      seconds_ + seconds_since(start)});
        }
    }
    seconds_ += seconds_since(start);
}

void SplatRender::trace_wave() {
    const std::uint64_t wave = next_wave_;
    const std::uint64_t wave_chunks = std::min(kChunksPerWave, chunk_count_ - wave);
    next_wave_ += wave_chunks;
    std::fill(complete_.begin(), complete_.end(), std::uint8_t(0));
    // A chunk not started (the engine stops handing them out at an interrupt) stays incomplete.
    parallel_for(wave_chunks, {.threads = threads_, .stop = interrupt_requested}, [&](std::size_t c, int thread) {
        const std::uint64_t first = (wave + c) * chunk_;
        const ChunkTraced traced = trace_chunk(first, std::min(path_count_, first + chunk_), settings_.seed, trace_,
                                               films_[c], rays_per_thread_[std::size_t(thread)]);
        contributing_[c] = traced.contributing;
        complete_[c] = traced.complete ? 1 : 0;
    });
    // The merge, in chunk order: the same sums whatever thread traced which chunk. When interrupted, only the
    // chunks before the first incomplete one, so the image averages paths 0 … traced − 1.
    for (std::uint64_t c = 0; c < wave_chunks; ++c) {
        if (!complete_[c]) {
            interrupted_ = true;
            break;
        }
        const std::vector<Color>& film = films_[c].pixels();
        for (std::size_t p = 0; p < pixels_; ++p) sums_[p] += Vec3d(film[p]);
        contributed_ += contributing_[c];
        traced_ += std::min(path_count_, (wave + c + 1) * chunk_) - (wave + c) * chunk_;
    }
}

// I = (1 / N) Σ_paths (their splats), over the N paths traced so far.
Image SplatRender::image_so_far() const {
    Image image(settings_.width, settings_.height);
    const double scale = traced_ > 0 ? 1.0 / double(traced_) : 0.0;
    for (std::size_t p = 0; p < pixels_; ++p) image.pixels()[p] = Color(sums_[p] * scale);
    return image;
}

RayCounts SplatRender::rays_so_far() const {
    RayCounts rays;
    for (const RayCounts& c : rays_per_thread_) rays += c;
    return rays;
}

SplatResult SplatRender::result() const {
    SplatResult out;
    out.contributing_paths = contributed_;
    RenderResult& r = out.render;
    r.image = image_so_far();
    r.rays = rays_so_far();
    r.samples = traced_;
    r.samples_per_pixel = int(traced_ / std::max<std::uint64_t>(1, pixels_));
    r.interrupted = interrupted_;
    r.seconds = seconds_;
    return out;
}

}  // namespace rt
