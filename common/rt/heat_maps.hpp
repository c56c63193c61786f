// --heat FILE.png: what each pixel cost, as pictures. Three panels side by side, each in false colour from 0
// (black) to its largest value (white) with its colour bar: the rays per sample (every kind), the bounces per
// sample (reflection, refraction and indirect rays: the path length beyond the first hit) and the samples a
// pixel took (even, unless a render was interrupted). Measured by the render loop (RenderSettings::heat).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "rt/render_loop.hpp"

namespace rt {

// Writes the panels of a width × height render (staged, like every output); returns the summary's line: the
// largest value of each panel, or, when no pixel took a sample (a render that splats light paths instead of
// sampling pixels), that nothing was measured, and writes nothing.
std::string write_heat_maps(const std::vector<PixelHeat>& heat, int width, int height,
                            const std::filesystem::path& path);

}  // namespace rt
