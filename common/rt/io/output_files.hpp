// A run's output files: the PNG, the PFM beside it and, for a piece of a render, its film; all of them or
// none, checked for NaN and infinity first. Shared by the chapter executables (app.cpp) and rt_merge.
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

// No NaN or infinity may reach an image: one is a bug in the chapter, reported as a failure
// (std::runtime_error, exit 1).
void check_finite(const Image& image);

// A further image a run writes beside its own, as x.SUFFIX.pfm (chapter 10's x.noisy.pfm, x.albedo.pfm).
struct ExtraImage {
    std::string suffix;  // ".noisy"
    Image image;
    bool radiance = false;  // an estimate of the same radiance: the summary measures it against --reference
};

// Every file a run with the image `png` (--out) may write, for check_outputs (run_files.hpp): x.png and
// x.pfm, x.film when `film`, each `extra_images` suffix's x.SUFFIX.pfm, and what an interrupted run writes
// instead (x.partial.png, x.partial.pfm, x.partial.film, x.partial.SUFFIX.pfm).
std::vector<RunFile> image_outputs(const std::filesystem::path& png, bool film,
                                   const std::vector<std::string>& extra_images);

// Writes the PNG, the PFM beside it, the `extra` PFMs and, given `film`, the film beside them (x.png, x.pfm,
// x.SUFFIX.pfm, x.film): each is first written whole under its staging name (staged_file.hpp), then all are
// renamed into place together, with signals held back. Returns what it wrote, for the summary:
// "x.png and x.pfm" or "x.png, x.pfm and x.film" (names quoted where they need it).
std::string write_outputs(const Image& image, const std::filesystem::path& png, const Film* film = nullptr,
                          const std::vector<ExtraImage>& extra = {});

}  // namespace rt
