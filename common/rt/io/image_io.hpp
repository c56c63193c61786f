// Image files: PNG for people (tone-mapped, sRGB) and PFM for numbers (linear radiance, lossless floats).
// Every file is written under a staging name beside it (staged_file.hpp) and renamed, so a failed run never
// leaves half a file.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "rt/core/image.hpp"

namespace rt {

// sRGB transfer function of a linear value in [0, 1]: 12.92·c below 0.0031308, else 1.055·c^(1/2.4) − 0.055.
Real srgb_encode(Real linear);
// Its inverse, the sRGB EOTF (IEC 61966-2-1), of an encoded value c in [0, 1]: c / 12.92 up to 0.04045, else
// ((c + 0.055) / 1.055)^2.4. Not gamma 2.2, which is up to 0.0085 off (near c = 0.75) and, near black, many
// times too dark (60 times at c = 1/255).
Real srgb_decode(Real encoded);
// Tone mapping of the course: the value clamped to [0, 1] (exposure 1), then sRGB-encoded to 8 bits.
std::uint8_t to_display_byte(Real linear);

// Each under a staging name, then renamed into place (staged_file.hpp). Throws InputError (unwritable path)
// or std::runtime_error (write failure); an earlier file is left as it was. A run's PNG, PFM and film are
// written together, all or none, by output_files.hpp.
void write_png(const Image& image, const std::filesystem::path& path);
void write_pfm(const Image& image, const std::filesystem::path& path);
// The files' bytes into an open file; false when a write failed. The PNG is tone-mapped and sRGB-encoded; the
// PFM is "PF\n<width> <height>\n-1.0\n" then little-endian float RGB rows from the bottom up.
bool encode_png(const Image& image, std::FILE* file);
bool encode_pfm(const Image& image, std::FILE* file);
// What read_pfm accepts in a pixel: any finite value, or radiance (finite and >= 0, as a reference image's).
enum class PfmPixels { kFinite, kRadiance };
// Reads a colour PFM ("PF"), either byte order, scale 1 (its magnitude, a unit for the pixels, is taken by no
// reader of the course: another is refused). Throws InputError naming the file and what is wrong.
Image read_pfm(const std::filesystem::path& path, PfmPixels pixels = PfmPixels::kFinite);
// Throws InputError "NAME: pixel (X, Y) must be finite, got R G B" (or "finite radiance, >= 0") when `c`
// is not what `pixels` accepts: the rule of every reader of radiance images (PFM, OpenEXR).
void check_read_pixel(const std::string& name, const Color& c, int x, int y, PfmPixels pixels);

// Checks before rendering that `path` can be written: it is not a folder, and its folder exists, is a folder
// and takes the staging file a write would use (created there and removed). Throws InputError naming why.
void check_writable(const std::filesystem::path& path);
// The same for the file a flag names, before any render of the run: the message starts with the flag
// ("--csv: ...").
void check_writable(const std::string& flag, const std::filesystem::path& path);
// Checks that `path` is a file to read: throws InputError "NAME: must be KIND, got no such file" (or what
// else it is: a folder, a link that cannot be followed).
void check_regular_file(const std::filesystem::path& path, const std::string& kind);

}  // namespace rt
