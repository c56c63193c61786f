#include "rt/core/image.hpp"

#include <string>

#include "rt/core/errors.hpp"
#include "rt/core/memory_limit.hpp"
#include "rt/core/pixel_sums.hpp"

namespace rt {

void check_image_size(long long width, long long height) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) throw InputError("image size must be positive, got " + size);
    if (width > kMaxImageSide || height > kMaxImageSide) {
        throw InputError("image size " + size + " is too large: at most " + std::to_string(kMaxImageSide) +
                         " pixels a side");
    }
    check_fits_in_memory(double(width) * double(height) * double(sizeof(Color) + sizeof(PixelSum)),
                         "image size " + size);
}

Image::Image(int width, int height) : width_(width), height_(height) {
    check_image_size(width, height);
    pixels_.assign(std::size_t(width) * std::size_t(height), Color(0));
}

double Image::mean() const {
    double sum = 0;
    for (const Color& c : pixels_) sum += double(c.r) + double(c.g) + double(c.b);
    return pixels_.empty() ? 0.0 : sum / (3.0 * double(pixels_.size()));
}

bool Image::all_finite() const {
    for (const Color& c : pixels_) {
        if (!is_finite(c)) return false;
    }
    return true;
}

}  // namespace rt
