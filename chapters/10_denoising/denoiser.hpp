// The denoisers of the chapter, one knob: --denoiser none|bilateral|atrous, each timed, since a filter's
// time is part of what it costs to reach an error.
#pragma once

#include <string>
#include <vector>

#include "atrous.hpp"
#include "bilateral.hpp"
#include "feature_buffers.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/core/image.hpp"

namespace rt {

enum class Denoiser { kNone, kBilateral, kAtrous };

constexpr auto names_of(Denoiser) {
    return enum_names<Denoiser>(
        "--denoiser", {{Denoiser::kNone, "none"}, {Denoiser::kBilateral, "bilateral"}, {Denoiser::kAtrous, "atrous"}});
}

struct DenoiseSettings {
    BilateralSettings bilateral;
    AtrousSettings atrous;
    int threads = 0;  // 0: one per core
};

struct Denoised {
    Image image;
    double seconds = 0;  // the filter's own time (wall clock), guide preparation included
};

// buffers.colour filtered by `denoiser` (kNone: as it is, in no time).
Denoised denoise(const FeatureBuffers& buffers, Denoiser denoiser, const DenoiseSettings& settings);

// What the summary says: the denoiser with its parameters, and its time against the render's.
std::vector<std::string> denoise_notes(Denoiser denoiser, const DenoiseSettings& settings, const Denoised& denoised,
                                       double render_seconds);

}  // namespace rt
