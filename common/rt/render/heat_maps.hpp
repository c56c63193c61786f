// --heat FILE.png: what each pixel cost, as pictures. Three panels side by side, each in false colour from 0
// (black) to its largest value (white) with its colour bar: the rays per sample (every kind), the bounces per
// sample (reflection, refraction and indirect rays: the path length beyond the first hit) and the samples a
// pixel took (even, unless a render was interrupted). The render loop measures them for its observer
// (render_observer.hpp), which HeatMaps is.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "rt/render/render_observer.hpp"

namespace rt {

class HeatMaps final : public RenderObserver {
public:
    HeatMaps(int width, int height);

    bool measures_cost() const override { return true; }
    void add_cost(int x, int y, const PixelCost& cost) override;

    // Writes the panels (staged, like every output); returns the summary's line: the largest value of each
    // panel, or, when no pixel took a sample (a render that splats light paths instead of sampling pixels),
    // that nothing was measured, and writes nothing.
    std::string write(const std::filesystem::path& path) const;

private:
    int width_;
    int height_;
    std::vector<PixelCost> cost_;  // row by row
};

}  // namespace rt
