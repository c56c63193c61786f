// The structural similarity index (Wang, Bovik, Sheikh and Simoncelli 2004), which compares what the eye
// compares: local means, contrasts and structure, rather than squared differences. Over a Gaussian window
// (σ = 1.5 pixels, 11×11) around each pixel, for images a and b,
//   SSIM = (2 μ_a μ_b + C1)(2 σ_ab + C2) / ((μ_a² + μ_b² + C1)(σ_a² + σ_b² + C2)),
// C1 = (0.01 L)², C2 = (0.03 L)², L = 1, averaged over every pixel and channel. It is computed on what the
// PNG shows (each channel clamped to [0, 1] and sRGB-encoded), since it is a measure of a picture. 1 means
// identical; it is symmetric in a and b.
#pragma once

#include "rt/core/image.hpp"

namespace rt {

// Throws InputError when the sizes differ. Windows are cut at the image's border (normalised inside).
double ssim(const Image& a, const Image& b);

}  // namespace rt
