// Image files: PNG for people (tone-mapped, sRGB) and PFM for numbers (linear radiance, lossless floats).
// Every file is written to a temporary name beside it and renamed, so a failed run never leaves half a file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "rt/image.hpp"

namespace rt {

// sRGB transfer function of a linear value in [0, 1]: 12.92·c below 0.0031308, else 1.055·c^(1/2.4) − 0.055.
Real srgb_encode(Real linear);
// Tone mapping of the course: the value clamped to [0, 1] (exposure 1), then sRGB-encoded to 8 bits.
std::uint8_t to_display_byte(Real linear);

// Throws InputError (unwritable path) or std::runtime_error (write failure); an earlier file is left as it was.
void write_png(const Image& image, const std::filesystem::path& path);
void write_pfm(const Image& image, const std::filesystem::path& path);
// Reads a colour PFM ("PF"), either byte order. Throws InputError naming the file and what is wrong.
Image read_pfm(const std::filesystem::path& path);

// Checks before rendering that `path` can be created: its folder exists and is writable.
void check_writable(const std::filesystem::path& path);
// Checks that `path` is a file to read: throws InputError "NAME: must be KIND, got no such file" (or "got
// something else (a folder?)").
void check_regular_file(const std::filesystem::path& path, const std::string& kind);

}  // namespace rt
