#include "ssim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "rt/core/errors.hpp"
#include "rt/io/image_io.hpp"

namespace rt {
namespace {

constexpr int kRadius = 5;  // the 11×11 window
constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;

// One channel of what the PNG shows.
std::vector<double> display_channel(const Image& image, int c) {
    std::vector<double> out(image.pixel_count());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = double(srgb_encode(std::clamp(image.pixels()[i][c], Real(0), Real(1))));
    return out;
}

}  // namespace

double ssim(const Image& a, const Image& b) {
    if (a.width() != b.width() || a.height() != b.height()) {
        throw InputError("ssim: the images are " + std::to_string(a.width()) + "x" +
                         std::to_string(a.height()) + " and " + std::to_string(b.width()) + "x" +
                         std::to_string(b.height()));
    }
    const int w = a.width(), h = a.height();
    std::array<double, 2 * kRadius + 1> g{};
    for (int i = -kRadius; i <= kRadius; ++i)
        g[std::size_t(i + kRadius)] = std::exp(-i * i / (2 * 1.5 * 1.5));
    double sum = 0;
    for (int c = 0; c < 3; ++c) {
        const std::vector<double> x = display_channel(a, c), y = display_channel(b, c);
        for (int py = 0; py < h; ++py) {
            for (int px = 0; px < w; ++px) {
                double weight = 0, mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
                for (int dy = -kRadius; dy <= kRadius; ++dy) {
                    const int qy = py + dy;
                    if (qy < 0 || qy >= h) continue;
                    for (int dx = -kRadius; dx <= kRadius; ++dx) {
                        const int qx = px + dx;
                        if (qx < 0 || qx >= w) continue;
                        const double gw = g[std::size_t(dy + kRadius)] * g[std::size_t(dx + kRadius)];
                        const std::size_t q = std::size_t(qy) * std::size_t(w) + std::size_t(qx);
                        weight += gw;
                        mx += gw * x[q];
                        my += gw * y[q];
                        // Each product formed the same way, so that SSIM(a, b) is SSIM(b, a) and SSIM(a, a)
                        // is 1 to the last bit.
                        xx += gw * (x[q] * x[q]);
                        yy += gw * (y[q] * y[q]);
                        xy += gw * (x[q] * y[q]);
                    }
                }
                mx /= weight, my /= weight;
                const double vx = xx / weight - mx * mx, vy = yy / weight - my * my;
                const double cxy = xy / weight - mx * my;
                sum += (2 * mx * my + kC1) * (2 * cxy + kC2) / ((mx * mx + my * my + kC1) * (vx + vy + kC2));
            }
        }
    }
    return sum / (3.0 * double(w) * double(h));
}

}  // namespace rt
