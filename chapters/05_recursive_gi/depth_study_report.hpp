// `--depth-study` as chapter 05's executable runs it: in the furnace (the scene given, when it is one, else
// the course's ch05_furnace.json at its own image size and samples, unless the flags set them), the depth
// rule at each of the study's depths, Russian roulette and the throughput rule at each threshold, with light
// sampling and without; the table on stdout and, when asked, as CSV.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "rt/core/effect_set.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"
#include "termination_flags.hpp"

namespace rt {

struct DepthStudyRequest {
    std::vector<int> depths{1, 2, 4, 8, 16};
    std::vector<Real> throughputs{Real(0.01), Real(0.1)};
    std::string csv;  // empty: no CSV
};

// `cli` tells which of --width, --height and --spp were given; `termination` gives the cap (--max-depth),
// the threshold and roulette's first depth.
void run_depth_study(const Scene& given, const CLI::App& cli, RenderSettings settings,
                     const EffectSet& simulated, const TerminationFlags& termination,
                     const DepthStudyRequest& request);

}  // namespace rt
