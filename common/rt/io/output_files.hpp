// A run's output files: the PNG, the radiance beside it (a PFM, or the OpenEXR file that --out named) and,
// for a piece of a render, its film; all of them or none, checked for NaN and infinity first. Shared by the
// chapter executables (app.cpp) and rt_merge.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "rt/core/image.hpp"
#include "rt/io/film.hpp"
#include "rt/io/run_files.hpp"

namespace rt {

// x.png with `suffix` and `extension`: with_suffix("a/x.png", ".partial", ".pfm") is "a/x.partial.pfm".
std::filesystem::path with_suffix(const std::filesystem::path& png, const std::string& suffix,
                                  const std::string& extension);

// How a run writes its radiance: --out x.png writes x.png and x.pfm; --out x.exr writes x.exr, of half floats
// or (--exr-float) of floats, and x.png (exr_file.hpp).
enum class RadianceFormat { kPfm, kExrHalf, kExrFloat };

// The image files --out names.
struct ImageOutput {
    std::filesystem::path path;  // as --out gave it: x.png or x.exr
    RadianceFormat format = RadianceFormat::kPfm;
    // x.png and x.pfm (or x.exr), with `suffix` before the extension: picture(".partial") is x.partial.png.
    std::filesystem::path picture(const std::string& suffix = "") const;
    std::filesystem::path radiance(const std::string& suffix = "") const;
    // What an interrupted run writes instead: x.partial.png or x.partial.exr.
    ImageOutput partial() const;
};

// Reads --out and --exr-float: a name ending in .png or .exr, with a name before it (.exr where the build has
// OpenEXR), and --exr-float only with .exr. Throws InputError starting "--out: " or "--exr-float: ".
ImageOutput image_output(const std::filesystem::path& out, bool exr_float);

// No NaN or infinity may reach an image: one is a bug in the chapter, reported as a failure
// (std::runtime_error, exit 1).
void check_finite(const Image& image);

// A further image a run writes beside its own, as x.SUFFIX.pfm (chapter 10's x.noisy.pfm, x.albedo.pfm), or
// x.SUFFIX.exr where the run's radiance is an EXR.
struct ExtraImage {
    std::string suffix;  // ".noisy"
    Image image;
    bool radiance = false;  // an estimate of the same radiance: the summary measures it against --reference
};

// Every file a run with the image `out` (--out) may write, for check_outputs (run_files.hpp): x.png and
// x.pfm (or x.exr), x.film when `film`, each `extra_images` suffix's x.SUFFIX.pfm (or .exr), and what an
// interrupted run writes instead (x.partial.png, x.partial.pfm, x.partial.film, x.partial.SUFFIX.pfm).
std::vector<RunFile> image_outputs(const ImageOutput& out, bool film,
                                   const std::vector<std::string>& extra_images);

// Writes the PNG, the radiance beside it, the `extra` images and, given `film`, the film beside them (x.png,
// x.pfm, x.SUFFIX.pfm, x.film): each is first written whole under its staging name (staged_file.hpp), then
// all are renamed into place together, with signals held back. Returns what it wrote, for the summary:
// "x.png and x.pfm", "x.exr and x.png" or "x.png, x.pfm and x.film" (names quoted where they need it; a
// half-float file with channels beyond its range says how many it holds as ±65504).
std::string write_outputs(const Image& image, const ImageOutput& out, const Film* film = nullptr,
                          const std::vector<ExtraImage>& extra = {});

}  // namespace rt
