// Chapter 09's three studies as its executable runs them, each printing its table on stdout: --walk-study
// (walk lengths against the mean free path and the albedo), --knob-study (the scene's error and time for each
// cap on scattering events, roulette on and off, against an uncapped reference) and --free-flight-study
// (spectral MIS against the naive per-channel density).
#pragma once

#include <CLI/CLI.hpp>
#include <vector>

#include "06_monte_carlo/path_tracer.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

struct MediaStudies {
    bool walk = false;
    int walk_paths = 4000;  // per row of the walk study
    bool knobs = false;
    std::vector<int> caps{1, 2, 4, 8, 16, 32, 64, 10000};
    int reference_spp = 1024;  // the knob study's uncapped reference
    bool free_flight = false;

    bool any() const { return walk || knobs || free_flight; }
};

void add_media_study_flags(CLI::App& app, MediaStudies& studies);

// Runs the study asked for; the knob study renders `scene` with `options` (its effects set).
void run_media_study(const MediaStudies& studies, const Scene& scene, const RenderSettings& settings,
                     const PathOptions& options);

}  // namespace rt
