// The denoisers of the chapter, one knob: --denoiser none|bilateral|atrous, each timed, since a filter's
// time is part of what it costs to reach an error.
#pragma once

#include <string>
#include <string_view>

#include "atrous.hpp"
#include "bilateral.hpp"
#include "feature_buffers.hpp"
#include "rt/image.hpp"

namespace rt {

enum class Denoiser { kNone, kBilateral, kAtrous };

// "none", "bilateral", "atrous".
std::string_view to_string(Denoiser denoiser);
// Throws InputError for another name.
Denoiser denoiser_from_string(const std::string& name);

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

}  // namespace rt
