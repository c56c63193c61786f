// The random walk's cost and its knobs, measured.
//  - walk_lengths: how many scattering events a path makes inside a sphere of a medium (radius 1, index
//    matched, under a uniform sky), against the mean free path 1 / σ_t and the albedo ω: high albedo and a
//    short mean free path make long walks (absorption ends one after about 1 / (1 − ω) events, crossing a body
//    of optical radius R σ_t takes about (R σ_t)²: the lesson measures both together).
//  - walk_knobs: the error (against an uncapped reference) and the time of a render with a cap on scattering
//    events, with and without Russian roulette in the medium.
//  - free_flight_study: spectral MIS against the naive per-channel density on a chromatic medium.
#pragma once

#include <vector>

#include "06_monte_carlo/path_tracer.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

struct WalkLengthRow {
    double mean_free_path = 0;
    double albedo = 0;
    double events_per_path = 0;  // mean scattering events in the medium per path that enters it
    std::uint64_t longest = 0;   // the most events one path made (a lower bound when capped)
    double ns_per_path = 0;
    double radiance = 0;  // the mean radiance returned (≤ 1: the furnace gives 1)
};
std::vector<WalkLengthRow> walk_lengths(const std::vector<double>& mean_free_paths,
                                        const std::vector<double>& albedos, int paths, std::uint64_t seed);

struct WalkKnobRow {
    int max_events = 0;
    bool roulette = true;
    double rmse = 0, mean_error = 0, seconds = 0;
};
// `scene` rendered with `settings` at each cap, roulette on and off, against `reference`.
std::vector<WalkKnobRow> walk_knobs(const Scene& scene, const RenderSettings& settings,
                                    const PathOptions& options, const Image& reference,
                                    const std::vector<int>& caps);

struct FreeFlightRow {
    int samples = 0;
    double rms_error_average = 0, rms_error_chosen = 0;  // relative, over `trials` estimates
    double max_weight_average = 0, max_weight_chosen = 0;
};
// Estimates of the probability of scattering before t_max (exactly 1 − e^(−σ_c t_max) in each channel) in a
// medium of albedo 1 and σ_t = `sigma_t`, by both weightings, `trials` times at each sample count.
std::vector<FreeFlightRow> free_flight_study(const Color& sigma_t, Real t_max,
                                             const std::vector<int>& samples, int trials, std::uint64_t seed);

}  // namespace rt
