// Splatting: a light path adds to whichever pixels it reaches, so pixels are written by many paths, in no
// order a thread could own. Deterministic for any thread count all the same: the N paths are cut into chunks
// of a fixed size (independent of the thread count), path i draws its random numbers from its own stream
// (Pcg32::for_sample(i, 0, seed)), each chunk splats into a film of its own, and the chunk films are added
// into the image in chunk order. The image is I = (1 / N) Σ_paths (their splats).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "rt/core/image.hpp"
#include "rt/core/random.hpp"
#include "rt/core/ray_counts.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

// Traces light path `index` with its own generator, adding its contributions to `film` (the pixel sums);
// returns whether it added anything.
using LightPathFunction = std::function<bool(std::uint64_t index, Pcg32& rng, Image& film, RayCounts& rays)>;

struct SplatResult {
    RenderResult render;                   // image = sums / paths traced; samples = paths traced
    std::uint64_t contributing_paths = 0;  // paths that added something to the image
};

// Paths per chunk: max(2^14, W H), so merging a chunk's film costs little beside tracing it.
std::uint64_t chunk_size(int width, int height);

// Traces `path_count` light paths on settings.threads threads (0: every core). Stops between chunks when
// interrupted: every 1024 paths a chunk looks at the flag, and an interrupted chunk is not merged (then
// `interrupted` is set and the image averages the paths of the chunks merged).
SplatResult render_light_paths(const RenderSettings& settings, std::uint64_t path_count,
                               const LightPathFunction& trace);

// render_light_paths taken in steps, with the same waves of chunks and so the same bits: trace_until(n)
// traces waves until n paths (or all) are merged, and result() is the image of the paths merged so far.
// Chapter 08's combined tracer traces its light paths this way, between the camera's passes
// (combined_render.hpp).
class SplatRender {
  public:
    SplatRender(const RenderSettings& settings, std::uint64_t path_count, LightPathFunction trace);
    void trace_until(std::uint64_t paths);
    SplatResult result() const;

  private:
    void trace_wave();  // the next kChunksPerWave chunks, merged in chunk order
    Image image_so_far() const;
    RayCounts rays_so_far() const;

    RenderSettings settings_;
    std::uint64_t path_count_;
    LightPathFunction trace_;
    int threads_;
    std::uint64_t chunk_;
    std::uint64_t chunk_count_;
    std::size_t pixels_;
    std::vector<Vec3d> sums_;   // of the films merged
    std::vector<Image> films_;  // one per chunk of a wave
    std::vector<std::uint64_t> contributing_;
    std::vector<std::uint8_t> complete_;
    std::vector<ThreadRayCounts> rays_per_thread_;
    std::uint64_t next_wave_ = 0;  // its first chunk
    std::uint64_t traced_ = 0, contributed_ = 0;
    bool interrupted_ = false;
    double seconds_ = 0;  // spent in trace_until
};

}  // namespace rt
