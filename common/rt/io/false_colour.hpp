// False colour for pictures of numbers (an error, rays per pixel): a ramp from black through blue, magenta,
// orange and yellow to white, and the linear colour that write_png turns into given display bytes, so such a
// picture is an Image like any other. Used by rt_compare's error panel and by --heat.
#pragma once

#include <array>
#include <cstdint>

#include "rt/core/image.hpp"

namespace rt {

// The ramp's colour at t in [0, 1] (clamped), as display bytes.
std::array<std::uint8_t, 3> false_colour(double t);
// The linear colour whose write_png bytes are `rgb` (the inverse of the sRGB encoding).
Color linear_of_display(const std::array<std::uint8_t, 3>& rgb);
// A vertical colour bar in columns [x0, x0 + width) of `image`: 0 (black) at the bottom, 1 (white) at the top.
void paint_colour_bar(Image& image, int x0, int width);

}  // namespace rt
