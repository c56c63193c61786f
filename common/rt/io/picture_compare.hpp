// Pictures as people see them: 8-bit sRGB, as a PNG holds them (image_io.hpp's tone mapping). A lesson's
// pictures are shipped as such PNGs, so a student checks a render against one (`--reference x.png`, the
// `rt_compare` tool, the stale-picture check) without the course's PFMs: the render is tone-mapped the same
// way and compared level by level, and the comparison says where the two differ.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "rt/core/image.hpp"

namespace rt {

struct Picture {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;  // row by row from the top left, 3 bytes a pixel
    std::uint8_t at(int x, int y, int channel) const {
        return rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3 + std::size_t(channel)];
    }
};

// Reads a PNG (any bit depth or colour type stb reads; alpha dropped, grey spread to RGB). Throws InputError
// naming the file and what is wrong.
Picture read_png(const std::filesystem::path& path);
// The picture write_png would write of the image: each channel through to_display_byte.
Picture to_picture(const Image& image);

// Where two pictures of one size differ. A pixel differs when one of its channels differs by more than
// `tolerance` levels (of 255).
struct PictureDifference {
    int width = 0;
    int height = 0;
    int tolerance = 0;
    long long differing = 0;  // pixels that differ
    int largest = 0;          // the largest difference of a channel, in levels
    double rmse = 0;          // over every channel of every pixel, in levels
    int min_x = 0, min_y = 0, max_x = -1, max_y = -1;  // the rectangle holding every differing pixel
    static constexpr int kGrid = 8;                    // the picture cut into kGrid × kGrid regions
    std::vector<long long> region_pixels, region_differing;
    double fraction() const { return width * height > 0 ? double(differing) / (double(width) * height) : 0; }
};

// Throws InputError when the sizes differ.
PictureDifference compare_pictures(const Picture& picture, const Picture& reference, int tolerance);
// Lines (each starting with `indent`) saying how many pixels differ and by how much, the rectangle that holds
// them and a map of the regions: ' ' none, '.' under 1 %, 'o' under 10 %, '#' 10 % or more of a region's
// pixels differ.
std::string describe(const PictureDifference& d, const std::string& indent);

}  // namespace rt
