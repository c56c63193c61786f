// Chapter 05's renders: each sample traces one camera ray (stratified in its pixel) and follows its path
// recursively; and the depth study, which renders the furnace once per termination rule and measures each
// against the exact answer Le / (1 − ρ).
#pragma once

#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "furnace.hpp"
#include "recursive_tracer.hpp"
#include "rt/core/effect_set.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

// What chapters 05 and 06 simulate (their ChapterInfo::supported): all but refraction and media.
inline constexpr EffectSet kRecursiveChapterEffects =
    EffectSet::all().without({Effect::kRefraction, Effect::kMedia});

RenderResult render_gi(const RecursiveTracer& tracer, const PinholeCamera& camera,
                       const RenderSettings& settings);

struct DepthStudyRow {
    TerminationSettings termination;
    bool light_sampling = true;  // direct light sampled (chapter 04), or found by indirect rays alone
    double mean = 0;             // over every pixel (the mean of its three channels)
    double standard_error = 0;   // of that mean: the pixels' standard deviation / √pixels
    double expected = 0;         // E[mean] in closed form; NaN where none is known (min throughput)
    double exact = 0;            // Le / (1 − ρ), the mean of the three channels
    double bias = 0;             // mean − exact, measured
    double rmse = 0;             // of the pixels against the exact image: √(bias² + noise²)
    double seconds = 0;          // render time, the median of 3 runs
    double rays_per_path = 0;    // every ray of the render / camera rays
};

// The furnace rendered once per rule (same size, samples and seed), each row timed and compared; with
// the effect "direct" not simulated the walls' light is found by indirect rays alone (no light sampling).
std::vector<DepthStudyRow> depth_study(const World& world, const Scene& scene, const Furnace& furnace,
                                       const PinholeCamera& camera, const RenderSettings& settings,
                                       const std::vector<TerminationSettings>& rules, DirectOptions direct);

// "depth 4", "throughput 0.01 (cap 64)", "roulette from 3 (cap 64)".
std::string describe(const TerminationSettings& termination);

// The study's table on stdout, and as CSV in `csv` when it is not empty.
void print_depth_study(const std::vector<DepthStudyRow>& rows, const Scene& scene, const Furnace& furnace,
                       const RenderSettings& settings, const std::string& csv);

}  // namespace rt
