#include "rt/core/error_metrics.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "rt/core/errors.hpp"

namespace rt {

ErrorMetrics compare(const Image& image, const Image& reference) {
    return compare(image, reference, PixelRect{0, 0, image.width(), image.height()});
}

ErrorMetrics compare(const Image& image, const Image& reference, const PixelRect& region) {
    if (image.width() != reference.width() || image.height() != reference.height()) {
        throw InputError("reference is " + std::to_string(reference.width()) + "x" +
                         std::to_string(reference.height()) + " but the image is " + std::to_string(image.width()) +
                         "x" + std::to_string(image.height()));
    }
    if (region.x0 < 0 || region.y0 < 0 || region.x1 > image.width() || region.y1 > image.height() ||
        region.x0 >= region.x1 || region.y0 >= region.y1)
        throw std::logic_error("compare: the region is empty or outside the image");
    double squared = 0, relative = 0, signed_sum = 0;
    for (int y = region.y0; y < region.y1; ++y) {
        for (int x = region.x0; x < region.x1; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double v = image.at(x, y)[c];
                const double r = reference.at(x, y)[c];
                const double d = v - r;
                squared += d * d;
                relative += d * d / (r * r + 0.01);
                signed_sum += d;
            }
        }
    }
    const double n = 3.0 * double(region.x1 - region.x0) * double(region.y1 - region.y0);
    return {std::sqrt(squared / n), relative / n, signed_sum / n};
}

}  // namespace rt
