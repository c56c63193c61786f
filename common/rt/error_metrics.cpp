#include "rt/error_metrics.hpp"

#include <cmath>
#include <string>

#include "rt/errors.hpp"

namespace rt {

ErrorMetrics compare(const Image& image, const Image& reference) {
    if (image.width() != reference.width() || image.height() != reference.height()) {
        throw InputError("reference is " + std::to_string(reference.width()) + "x" +
                         std::to_string(reference.height()) + " but the image is " + std::to_string(image.width()) +
                         "x" + std::to_string(image.height()));
    }
    double squared = 0, relative = 0, signed_sum = 0;
    for (std::size_t i = 0; i < image.pixel_count(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double x = image.pixels()[i][c];
            const double r = reference.pixels()[i][c];
            const double d = x - r;
            squared += d * d;
            relative += d * d / (r * r + 0.01);
            signed_sum += d;
        }
    }
    const double n = 3.0 * double(image.pixel_count());
    return {std::sqrt(squared / n), relative / n, signed_sum / n};
}

}  // namespace rt
