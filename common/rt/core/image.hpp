// An image of linear RGB radiance, row by row from the top left.
#pragma once

#include <cstddef>
#include <vector>

#include "rt/core/math.hpp"

namespace rt {

inline constexpr int kMaxImageSide = 1 << 16;
inline constexpr int kMaxSamplesPerPixel = 1 << 20;

// Throws InputError unless width and height are in [1, kMaxImageSide] and the buffers a render needs (its
// image and its exact sums, pixel_sums.hpp) fit in this machine's memory; the message gives the size it
// would need.
void check_image_size(long long width, long long height);

class Image {
public:
    Image() = default;
    // Throws InputError when width or height is not positive.
    Image(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t pixel_count() const { return pixels_.size(); }

    Color& at(int x, int y) { return pixels_[index(x, y)]; }
    const Color& at(int x, int y) const { return pixels_[index(x, y)]; }
    const std::vector<Color>& pixels() const { return pixels_; }
    std::vector<Color>& pixels() { return pixels_; }

    // The average of every channel of every pixel.
    double mean() const;
    // True when no channel of any pixel is NaN or infinite.
    bool all_finite() const;

private:
    std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width_) + std::size_t(x); }

    int width_ = 0;
    int height_ = 0;
    std::vector<Color> pixels_;
};

// Pixels x in [x0, x1), y in [y0, y1).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

}  // namespace rt
