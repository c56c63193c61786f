// OpenEXR files, the radiance format of compositors, tev and Blender: linear RGB, ZIP-compressed, as half
// floats (16 bits: about 3 significant digits, up to 65504) or floats, through the OpenEXR library where
// CMake found it (RT_HAVE_OPENEXR; Debian libopenexr-dev). Written under a staging name like every image
// (staged_file.hpp); read with the PFM's rules for a pixel (image_io.hpp's PfmPixels: no NaN, no infinity).
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>

#include "rt/core/image.hpp"
#include "rt/io/image_io.hpp"

namespace rt {

// Whether this build reads and writes OpenEXR files.
bool has_openexr();

// How an EXR stores its channels.
enum class ExrChannels { kHalf, kFloat };
// The largest finite half float. A half-float file holds a channel beyond ±65504 as ±65504, never as an
// infinity (which no reader of the course takes back).
inline constexpr float kHalfMax = 65504.f;
// How many channel values of `image` a half-float file holds as ±kHalfMax instead.
std::size_t beyond_half_range(const Image& image);

// The EXR's bytes into an open file (R, G and B, the data window from (0, 0)); false when a write failed.
// Throws InputError where the build has no OpenEXR.
bool encode_exr(const Image& image, ExrChannels channels, std::FILE* file);
// Under a staging name, then renamed into place, as write_pfm.
void write_exr(const Image& image, const std::filesystem::path& path, ExrChannels channels);
// Reads the R, G and B channels (half, float or unsigned; scanlines or tiles) of an OpenEXR file, its data
// window as the image. Throws InputError naming the file and what is wrong: not a file, not OpenEXR, no R, G
// or B channel, truncated, a pixel `pixels` does not take, or a build without OpenEXR.
Image read_exr(const std::filesystem::path& path, PfmPixels pixels = PfmPixels::kFinite);

// A radiance image as its name says: a .exr through read_exr, anything else through read_pfm.
Image read_radiance(const std::filesystem::path& path, PfmPixels pixels = PfmPixels::kFinite);

}  // namespace rt
