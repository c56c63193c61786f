// The image of an environment light (assets/scenes/README.md, "lights"): linear RGB radiance in
// latitude–longitude, read from a Radiance .hdr (stb_image), a colour PFM, or an OpenEXR file where the course
// was built with OpenEXR (exr_file.hpp). Every pixel must be finite and >= 0.
#pragma once

#include <filesystem>

#include "rt/core/image.hpp"

namespace rt {

// Throws InputError naming the file and what is wrong with it (no such file, a kind it does not read, a
// broken or truncated file, a negative or non-finite pixel, an image too large for memory).
Image read_environment_image(const std::filesystem::path& path);

}  // namespace rt
