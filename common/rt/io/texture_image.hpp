// A texture's image file (PNG or JPEG, through stb_image), read once when the scene is loaded, into linear
// RGB texels: each 8-bit value decoded by the sRGB EOTF (srgb_decode), or taken as it is for a "linear"
// image.
#pragma once

#include <filesystem>

#include "rt/core/scene.hpp"

namespace rt {

// The largest side a texture may have, in texels (a 4096 × 4096 image is 192 MiB of linear texels).
inline constexpr int kLargestTextureSide = 4096;

// Throws InputError, without the file's name (the scene loader puts it in front with the key's place):
// "no such file", "stb_image cannot read it (why)", a side larger than kLargestTextureSide.
TextureImage read_texture_image(const std::filesystem::path& path, bool srgb);

}  // namespace rt
