#include "rt/render/heat_maps.hpp"

#include <algorithm>
#include <cstdio>

#include "rt/io/false_colour.hpp"
#include "rt/io/image_io.hpp"

namespace rt {

HeatMaps::HeatMaps(int width, int height)
    : width_(width), height_(height), cost_(std::size_t(width) * std::size_t(height)) {}

void HeatMaps::add_cost(int x, int y, const PixelCost& cost) {
    PixelCost& sum = cost_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
    sum.rays += cost.rays;
    sum.bounces += cost.bounces;
    sum.samples += cost.samples;
}

std::string HeatMaps::write(const std::filesystem::path& path) const {
    const int width = width_, height = height_;
    std::uint64_t sampled = 0;
    for (const PixelCost& h : cost_) sampled += h.samples;
    if (sampled == 0) return "heat maps: not measured (this render does not sample pixels); nothing written";
    // The three measures of a pixel, per sample where that is what they mean.
    auto measure = [&](const PixelCost& h, int panel) {
        const double n = double(std::max<std::uint64_t>(h.samples, 1));
        return panel == 0 ? double(h.rays) / n : panel == 1 ? double(h.bounces) / n : double(h.samples);
    };
    double largest[3] = {0, 0, 0};
    for (const PixelCost& h : cost_)
        for (int panel = 0; panel < 3; ++panel) largest[panel] = std::max(largest[panel], measure(h, panel));
    constexpr int kGap = 4, kBar = 12;
    const int panel_width = width + kBar + kGap;
    Image canvas(3 * panel_width + 2 * kGap, height);
    for (Color& c : canvas.pixels()) c = Color(Real(0.2));
    for (int panel = 0; panel < 3; ++panel) {
        const int x0 = panel * (panel_width + kGap);
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const double v = measure(cost_[std::size_t(y) * std::size_t(width) + std::size_t(x)], panel);
                canvas.at(x0 + x, y) = linear_of_display(false_colour(largest[panel] > 0 ? v / largest[panel] : 0));
            }
        }
        paint_colour_bar(canvas, x0 + width + kGap, kBar);
    }
    write_png(canvas, path);
    char line[256];
    std::snprintf(line, sizeof line,
                  "heat maps in %s: rays per sample (up to %.3g) | bounces per sample (up to %.3g) | samples "
                  "(up to %.0f); each bar from 0 (black) to its largest (white)",
                  path.string().c_str(), largest[0], largest[1], largest[2]);
    return line;
}

}  // namespace rt
