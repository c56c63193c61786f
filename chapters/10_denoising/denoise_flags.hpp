// Chapter 10's flags: --study and its options, --denoiser, and the filters' parameters, each refused unless
// the denoiser that takes it (or the study, which runs both filters) is chosen; and chapter 05's termination.
#pragma once

#include <CLI/CLI.hpp>

#include "05_recursive_gi/termination_flags.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "denoise_study.hpp"
#include "denoiser.hpp"

namespace rt {

struct DenoiseFlags {
    bool study = false;
    StudyOptions study_options;
    Denoiser denoiser = Denoiser::kAtrous;
    DenoiseSettings settings;
    EdgeStopping edges;  // both filters' edge stopping
    // The paths' termination: chapter 06's rule unless the flags or the scene say otherwise.
    TerminationFlags termination{PathOptions{}.termination, std::nullopt};

    // The settings with `edges` in both filters, on `threads` threads.
    DenoiseSettings resolved(int threads) const;
};

void add_denoise_flags(CLI::App& app, DenoiseFlags& flags);

}  // namespace rt
