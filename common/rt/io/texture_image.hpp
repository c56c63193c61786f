// A texture's image file (PNG or JPEG, known by its first bytes; through stb_image, which would also decode
// GIF, BMP, TGA, PPM, HDR or PSD, refused here), read once when the scene is loaded, into linear
// RGB texels: each 8-bit value decoded by the sRGB EOTF (srgb_decode), or taken as it is for a "linear"
// image.
#pragma once

#include <filesystem>

#include "rt/core/scene.hpp"

namespace rt {

// The largest side a texture may have, in texels (a 4096 × 4096 image is 192 MiB of linear texels).
inline constexpr int kLargestTextureSide = 4096;

// Throws InputError, without the file's name (the scene loader puts it in front with the key's place):
// "no such file", another kind of image, "stb_image cannot read it (why)", a side larger than
// kLargestTextureSide, or what check_png finds (a damaged chunk, a palette index past the palette).
TextureImage read_texture_image(const std::filesystem::path& path, bool srgb);

}  // namespace rt
