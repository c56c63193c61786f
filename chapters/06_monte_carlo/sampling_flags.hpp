// The flags of this chapter's sampling, which every later chapter's paths take too: --sampling (how the
// path loop draws directions, with chapter 04's --quad-lights: how a light sample draws a quad's) and
// --sampler (where a sample's numbers come from).
#pragma once

#include <CLI/CLI.hpp>

#include "04_direct_lighting/quad_light_strategy.hpp"
#include "sample_stream.hpp"
#include "sampling_strategy.hpp"

namespace rt {

// Adds --sampling and --quad-lights; returns --sampling.
CLI::Option* add_sampling_flag(CLI::App& app, SamplingStrategy& strategy, QuadLightSampling& quad_lights);
CLI::Option* add_sampler_flag(CLI::App& app, PointSet& points);

}  // namespace rt
