// The flags of this chapter's sampling, which every later chapter's paths take too: --sampling (how the
// path loop draws directions) and --sampler (where a sample's numbers come from).
#pragma once

#include <CLI/CLI.hpp>

#include "sample_stream.hpp"
#include "sampling_strategy.hpp"

namespace rt {

CLI::Option* add_sampling_flag(CLI::App& app, SamplingStrategy& strategy);
CLI::Option* add_sampler_flag(CLI::App& app, PointSet& points);

}  // namespace rt
