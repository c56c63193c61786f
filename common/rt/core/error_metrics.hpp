// How far an image is from a reference, over every channel of every pixel.
#pragma once

#include "rt/core/image.hpp"

namespace rt {

struct ErrorMetrics {
    double rmse = 0;          // sqrt(mean((x − r)²))
    double relative_mse = 0;  // mean((x − r)² / (r² + 0.01)), the relative error that dark pixels do not blow up
    double mean_error = 0;    // mean(x − r): the bias, signed
};

// Throws InputError when the sizes differ.
ErrorMetrics compare(const Image& image, const Image& reference);
// The same over the pixels of `region` only (a crop: the caustic under a glass sphere, a lamp's edge).
ErrorMetrics compare(const Image& image, const Image& reference, const PixelRect& region);

}  // namespace rt
