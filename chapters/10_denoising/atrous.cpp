#include "atrous.hpp"

#include "rt/render/parallel_for.hpp"

namespace rt {

GuidePixel atrous_pixel(const std::vector<GuidePixel>& level, int width, int height, int x, int y, int step,
                        const EdgeStopping& edges, Real* weights) {
    // EXERCISE(ch10.atrous_pixel) § The à-trous wavelet filter
    const GuidePixel& p = level[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    Color sum(0);
    Real total = 0, variance = 0;
    for (int j = 0; j < 5; ++j) {
        const int qy = y + (j - 2) * step;
        for (int k = 0; k < 5; ++k) {
            const int qx = x + (k - 2) * step;
            if (weights) weights[j * 5 + k] = 0;
            if (qx < 0 || qx >= width || qy < 0 || qy >= height) continue;
            const GuidePixel& q = level[std::size_t(qy) * std::size_t(width) + std::size_t(qx)];
            // h(q) relative to the centre tap's (3/8)², which the normalisation cancels: the centre then
            // weighs exactly 1, so a pixel that no neighbour may join keeps its colour to the bit.
            const Real h = kB3Taps[std::size_t(j)] * kB3Taps[std::size_t(k)] / (kB3Taps[2] * kB3Taps[2]);
            const Real w = h * edge_stopping_weight(p, q, edges);
            if (weights) weights[j * 5 + k] = w;
            sum += w * q.colour;
            total += w;
            variance += w * w * q.variance;
        }
    }
    // total ≥ 1: the centre tap weighs 1.
    GuidePixel out = p;
    out.colour = sum / total;
    out.variance = variance / (total * total);
    if (weights)
        for (int i = 0; i < 25; ++i) weights[i] /= total;
    return out;
    // END EXERCISE
}

Image atrous_filter(const FeatureBuffers& buffers, const AtrousSettings& settings, int threads) {
    const int width = buffers.colour.width(), height = buffers.colour.height();
    std::vector<GuidePixel> level = guide_pixels(buffers), next(level.size());
    for (int i = 0, step = 1; i < settings.levels; ++i, step *= 2) {
        parallel_for(std::size_t(height), {.threads = threads}, [&](std::size_t row, int) {
            const int y = int(row);
            for (int x = 0; x < width; ++x)
                next[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
                    atrous_pixel(level, width, height, x, y, step, settings.edges);
        });
        level.swap(next);
    }
    Image out(width, height);
    for (std::size_t i = 0; i < level.size(); ++i) out.pixels()[i] = level[i].colour;
    return out;
}

}  // namespace rt
