// A render's 2 × 2 blocks over independent runs: each block's mean over the runs and the standard error of that
// mean. Two estimators of the same image agree when every block's means are within a few of their errors.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "rt/core/image.hpp"

namespace rt::test {

struct BlockMeans {
    std::array<double, 4> mean{};
    std::array<double, 4> error{};
};

// `render(seed)` gives one run's image (square, `size` pixels a side); the runs use seeds 50, 51, ….
template <typename Render>
BlockMeans block_means(int size, int runs, Render&& render) {
    std::array<double, 4> sum{}, sum2{};
    for (int r = 0; r < runs; ++r) {
        const Image image = render(50 + std::uint64_t(r));
        std::array<double, 4> block{};
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const Color& c = image.at(x, y);
                block[std::size_t((y * 2 / size) * 2 + x * 2 / size)] +=
                    double(c.r + c.g + c.b) / (3.0 * size * size / 4);
            }
        for (std::size_t b = 0; b < 4; ++b) sum[b] += block[b], sum2[b] += block[b] * block[b];
    }
    BlockMeans out;
    for (std::size_t b = 0; b < 4; ++b) {
        out.mean[b] = sum[b] / runs;
        out.error[b] = std::sqrt(std::max(0.0, sum2[b] / runs - out.mean[b] * out.mean[b]) / (runs - 1));
    }
    return out;
}

}  // namespace rt::test
