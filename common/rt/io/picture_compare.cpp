#include "rt/io/picture_compare.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/image_io.hpp"

namespace rt {

Picture read_png(const std::filesystem::path& path) {
    check_regular_file(path, "a PNG file");
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load(path.c_str(), &width, &height, &channels, 3), stbi_image_free);
    if (!data) {
        throw InputError(shown(path) + ": must be a PNG file, got one stb_image cannot read (" +
                         stbi_failure_reason() + ")");
    }
    Picture picture{width, height, {}};
    picture.rgb.assign(data.get(), data.get() + std::size_t(width) * std::size_t(height) * 3);
    return picture;
}

Picture to_picture(const Image& image) {
    Picture picture{image.width(), image.height(), {}};
    picture.rgb.reserve(image.pixel_count() * 3);
    for (const Color& c : image.pixels()) {
        for (int channel = 0; channel < 3; ++channel) picture.rgb.push_back(to_display_byte(c[channel]));
    }
    return picture;
}

PictureDifference compare_pictures(const Picture& picture, const Picture& reference, int tolerance) {
    if (picture.width != reference.width || picture.height != reference.height) {
        throw InputError("the reference picture is " + std::to_string(reference.width) + "x" +
                         std::to_string(reference.height) + ", the image " + std::to_string(picture.width) + "x" +
                         std::to_string(picture.height) + ": they must be the same size");
    }
    PictureDifference d;
    d.width = picture.width;
    d.height = picture.height;
    d.tolerance = tolerance;
    d.min_x = picture.width;
    d.min_y = picture.height;
    constexpr int kGrid = PictureDifference::kGrid;
    d.region_pixels.assign(kGrid * kGrid, 0);
    d.region_differing.assign(kGrid * kGrid, 0);
    double sum_squares = 0;
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            int largest = 0;
            for (int c = 0; c < 3; ++c) {
                const int difference = std::abs(int(picture.at(x, y, c)) - int(reference.at(x, y, c)));
                largest = std::max(largest, difference);
                sum_squares += double(difference) * difference;
            }
            const std::size_t region = std::size_t(y * kGrid / picture.height * kGrid + x * kGrid / picture.width);
            ++d.region_pixels[region];
            d.largest = std::max(d.largest, largest);
            if (largest > tolerance) {
                ++d.differing;
                ++d.region_differing[region];
                d.min_x = std::min(d.min_x, x);
                d.min_y = std::min(d.min_y, y);
                d.max_x = std::max(d.max_x, x);
                d.max_y = std::max(d.max_y, y);
            }
        }
    }
    d.rmse = std::sqrt(sum_squares / (3.0 * double(picture.width) * double(picture.height)));
    return d;
}

std::string describe(const PictureDifference& d, const std::string& indent) {
    char line[256];
    std::snprintf(line, sizeof line, "%s%lld of %lld pixels differ by more than %d of 255 (%.2f %%); largest "
                  "difference %d, RMSE %.3f levels\n",
                  indent.c_str(), d.differing, (long long)d.width * d.height, d.tolerance, 100 * d.fraction(),
                  d.largest, d.rmse);
    std::string text = line;
    if (d.differing == 0) return text;
    std::snprintf(line, sizeof line, "%sthey lie in x %d..%d, y %d..%d (from the top left); by region, %d x %d "
                  "(' ' none, '.' < 1 %%, 'o' < 10 %%, '#' more):\n",
                  indent.c_str(), d.min_x, d.max_x, d.min_y, d.max_y, PictureDifference::kGrid,
                  PictureDifference::kGrid);
    text += line;
    for (int row = 0; row < PictureDifference::kGrid; ++row) {
        text += indent + "  |";
        for (int column = 0; column < PictureDifference::kGrid; ++column) {
            const std::size_t region = std::size_t(row * PictureDifference::kGrid + column);
            const double share = d.region_pixels[region] > 0
                                     ? double(d.region_differing[region]) / double(d.region_pixels[region])
                                     : 0;
            text += d.region_differing[region] == 0 ? ' ' : share < 0.01 ? '.' : share < 0.1 ? 'o' : '#';
        }
        text += "|\n";
    }
    return text;
}

}  // namespace rt
