#include "rt/core/pixel_sums.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace rt {
namespace {

Real channel_mean(double sum, std::uint32_t count, std::uint32_t flags) {
    const bool plus = (flags & PixelSum::kPlusInfinity) != 0, minus = (flags & PixelSum::kMinusInfinity) != 0;
    if ((flags & PixelSum::kNan) != 0 || (plus && minus)) return std::numeric_limits<Real>::quiet_NaN();
    if (plus) return kInfinity;
    if (minus) return -kInfinity;
    if (count == 0) return 0;
    return Real(sum / double(count));
}

}  // namespace

// Without high parts (every sample below 2^50), the low part's value alone, converted once.
double PixelSum::total(int c) const {
    const std::size_t i = std::size_t(c);
    const double low = double(channels[i]) * 0x1p-56;
    return high_ ? double((*high_)[i]) * kHighUnit + low : low;
}

Color PixelSum::mean() const {
    Color m;
    for (int c = 0; c < 3; ++c) m[c] = channel_mean(total(c), count, (non_finite >> (3 * c)) & 7u);
    return m;
}

PixelSums::PixelSums(int width, int height)
    : width_(width), height_(height), pixels_(std::size_t(width) * std::size_t(height)) {}

void PixelSums::add(const PixelSums& other) {
    if (other.width_ != width_ || other.height_ != height_)
        throw std::logic_error("PixelSums::add: the sums are of different sizes");
    for (std::size_t i = 0; i < pixels_.size(); ++i) pixels_[i].add(other.pixels_[i]);
}

Image PixelSums::mean_image() const {
    Image image(width_, height_);
    for (std::size_t i = 0; i < pixels_.size(); ++i) image.pixels()[i] = pixels_[i].mean();
    return image;
}

std::uint32_t PixelSums::min_count() const {
    std::uint32_t fewest = std::numeric_limits<std::uint32_t>::max();
    for (const PixelSum& p : pixels_) fewest = std::min(fewest, p.count);
    return pixels_.empty() ? 0 : fewest;
}

std::uint64_t PixelSums::total_count() const {
    std::uint64_t total = 0;
    for (const PixelSum& p : pixels_) total += p.count;
    return total;
}

Color variance_of_mean(const PixelSum& sum, const PixelSum& squares) {
    const double n = double(sum.count);
    if (sum.count < 2) return Color(0);
    Color variance;
    for (int c = 0; c < 3; ++c) {
        const double total = sum.total(c), total_squares = squares.total(c);
        const double s2 = (total_squares - total * total / n) / (n - 1);
        variance[c] = Real(std::max(s2, 0.0) / n);
    }
    return variance;
}

Image variance_image(const PixelSums& sums, const PixelSums& squares) {
    if (squares.width() != sums.width() || squares.height() != sums.height())
        throw std::logic_error("variance_image: the sums are of different sizes");
    Image image(sums.width(), sums.height());
    for (std::size_t i = 0; i < sums.pixels().size(); ++i)
        image.pixels()[i] = variance_of_mean(sums.pixels()[i], squares.pixels()[i]);
    return image;
}

}  // namespace rt
