#include "bilateral.hpp"

#include <algorithm>
#include <cmath>

#include "rt/render/parallel_for.hpp"

namespace rt {
namespace {

// Calls visit(q index in the window, q's pixel index, w(p, q)) over pixel (x, y)'s window, inside the image;
// returns Σ w.
template <typename Visit>
Real visit_window(const std::vector<GuidePixel>& guides, int width, int height, int x, int y,
                  const BilateralSettings& settings, Visit&& visit) {
    const int r = bilateral_radius(settings);
    const Real inv_two_sigma2 = Real(1) / (2 * settings.spatial * settings.spatial);
    const GuidePixel& p = guides[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    Real total = 0;
    for (int dy = -r; dy <= r; ++dy) {
        const int qy = y + dy;
        if (qy < 0 || qy >= height) continue;
        for (int dx = -r; dx <= r; ++dx) {
            const int qx = x + dx;
            if (qx < 0 || qx >= width) continue;
            const std::size_t q = std::size_t(qy) * std::size_t(width) + std::size_t(qx);
            const Real spatial = std::exp(-Real(dx * dx + dy * dy) * inv_two_sigma2);
            const Real w = spatial * edge_stopping_weight(p, guides[q], settings.edges);
            visit(std::size_t((dy + r) * (2 * r + 1) + (dx + r)), q, w);
            total += w;
        }
    }
    return total;  // ≥ 1: the centre weighs exp(0) · 1
}

}  // namespace

int bilateral_radius(const BilateralSettings& settings) {
    return int(std::ceil(2 * settings.spatial));
}

std::vector<Real> bilateral_weights(const std::vector<GuidePixel>& guides, int width, int height, int x,
                                    int y, const BilateralSettings& settings) {
    const int r = bilateral_radius(settings);
    std::vector<Real> weights(std::size_t((2 * r + 1) * (2 * r + 1)), 0);
    const Real total = visit_window(guides, width, height, x, y, settings,
                                    [&](std::size_t i, std::size_t, Real w) { weights[i] = w; });
    for (Real& w : weights) w /= total;
    return weights;
}

Image bilateral_filter(const FeatureBuffers& buffers, const BilateralSettings& settings, int threads) {
    const int width = buffers.colour.width(), height = buffers.colour.height();
    const std::vector<GuidePixel> guides = guide_pixels(buffers);
    Image out(width, height);
    parallel_for(std::size_t(height), {.threads = threads}, [&](std::size_t row, int) {
        const int y = int(row);
        for (int x = 0; x < width; ++x) {
            Color sum(0);
            const Real total =
                visit_window(guides, width, height, x, y, settings,
                             [&](std::size_t, std::size_t q, Real w) { sum += w * guides[q].colour; });
            out.at(x, y) = sum / total;
        }
    });
    return out;
}

}  // namespace rt
