// A film: the exact per-pixel sums of some of a render's samples, with what it takes to add it to other
// pieces of the same render (rt_merge, MPI) or to continue it (--resume). The file format is in
// common/README.md ("The film file").
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "rt/core/pixel_sums.hpp"
#include "rt/core/sample_range.hpp"

namespace rt {

inline constexpr std::uint32_t kFilmVersion = 2;  // 1 had no high parts (pixel_sums.hpp)

// What makes two films pieces of one render: the same chapter, scene, flags, size, samples per pixel and
// seed.
struct FilmIdentity {
    std::string chapter;           // "ch06_monte_carlo"
    std::string scene;             // the scene file's name, for messages only
    std::uint64_t scene_hash = 0;  // FNV-1a of every file the scene read (scene_fingerprint)
    std::string options;           // the chapter's own flags as given, "--strategy=mis --max-depth=8"
    int width = 0;
    int height = 0;
    int samples_per_pixel = 0;  // of the whole render
    std::uint64_t seed = 0;

    bool operator==(const FilmIdentity&) const = default;
};

// Where `other` differs from `expected`, first difference only: "seed 2, expected 1"; empty when they match.
std::string first_difference(const FilmIdentity& expected, const FilmIdentity& other);

struct Film {
    FilmIdentity identity;
    SampleRange range;  // the samples asked for; pixel p holds range.first … range.first + count − 1
    PixelSums sums;

    // Every pixel holds all of `range` (an interrupted render's film does not).
    bool complete() const { return sums.min_count() == std::uint32_t(range.size()); }
};

// A film is input: every pixel must be what `range.size()` samples of a render can sum to — no more samples,
// no unknown flag, no NaN or infinite sample (the render that wrote it failed), no negative sum (radiance is
// never negative; 2^-16 a sample of rounding is let through) and no sum beyond its samples' limits
// (pixel_sums.hpp: each sample's part below 2^50 at most 2^50, its high part below kSampleLimit, so a whole
// render's sums, at most kMaxSamplesPerPixel samples, stay far inside 128 bits). Throws InputError naming `name` and the first pixel that is not.
void check_film_values(const Film& film, const std::string& name);

// The film's bytes into an open file (false when a write failed), and the film written all or nothing
// (staged_file.hpp).
bool encode_film(const Film& film, std::FILE* file);
void write_film(const Film& film, const std::filesystem::path& path);
// Throws InputError naming the file and what is wrong: not a film, another version, truncated, corrupt (the
// checksum), or values out of range (check_film_values).
Film read_film(const std::filesystem::path& path);

}  // namespace rt
