// Splatting: a light path adds to whichever pixels it reaches, so pixels are written by many paths, in no
// order a thread could own. Deterministic for any thread count all the same: the N paths are cut into chunks
// of a fixed size (independent of the thread count), path i draws its random numbers from its own stream
// (Pcg32::for_sample(i, 0, seed)), each chunk splats into a film of its own, and the chunk films are added
// into the image in chunk order. The image is I = (1 / N) Σ_paths (their splats).
#pragma once

#include <cstdint>
#include <functional>

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

}  // namespace rt
