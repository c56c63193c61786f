#include "rt/io/false_colour.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

std::array<std::uint8_t, 3> false_colour(double t) {
    constexpr std::array<std::array<double, 3>, 6> stops{
        {{0, 0, 0}, {0.1, 0.1, 0.6}, {0.65, 0.15, 0.55}, {0.95, 0.45, 0.1}, {1, 0.85, 0.15}, {1, 1, 1}}};
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * double(stops.size() - 1);
    const std::size_t i = std::min(std::size_t(t), stops.size() - 2);
    const double f = t - double(i);
    std::array<std::uint8_t, 3> rgb{};
    for (std::size_t c = 0; c < 3; ++c) rgb[c] = std::uint8_t(std::lround((stops[i][c] * (1 - f) + stops[i + 1][c] * f) * 255));
    return rgb;
}

Color linear_of_display(const std::array<std::uint8_t, 3>& rgb) {
    Color c;
    for (int k = 0; k < 3; ++k) {
        const double v = rgb[std::size_t(k)] / 255.0;
        c[k] = Real(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
    }
    return c;
}

void paint_colour_bar(Image& image, int x0, int width) {
    const int h = image.height();
    for (int y = 0; y < h; ++y) {
        const Color c = linear_of_display(false_colour(h > 1 ? double(h - 1 - y) / double(h - 1) : 1));
        for (int x = x0; x < x0 + width; ++x) image.at(x, y) = c;
    }
}

}  // namespace rt
