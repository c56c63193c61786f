// The sampler view's two answers. /samplers: every sampler of the registry
// (tests/support/sampler_registry.hpp) with its parameters.
// /sample?name=power_cosine&exponent=6[&samples=N][&seed=S]: that sampler drawn N times (10^6, as the tests)
// and counted in the 48 × 96 cells of the sphere's (cos θ, φ), or in 200 cells of its segment for a sampler
// of distances, beside the counts its pdf expects, the chi-square verdict of the tests' harness
// (chi_square_statistic.hpp: the same statistic and the same checks) at the course's level of 1 %, and the
// cells that fail on their own. Bad input (an unknown sampler or parameter, a value out of range) is answered
// 400 with one line saying what is wrong.
#pragma once

#include <vector>

#include "rt/live/live_server.hpp"
#include "support/chi_square_statistic.hpp"
#include "support/sampler_registry.hpp"

namespace rt::test {

// The level of the page's one test: α of the course (the test programs split it among their m tests).
inline constexpr double kSamplerViewLevel = 0.01;
inline constexpr int kSamplerViewMinSamples = 1000;

// The cells, of those expecting at least 5 (the statistic's own rule), whose term (O − E)² / E alone is
// unlikely at `level` once corrected for their number (sidak_level): where a wrong sampler shows.
std::vector<int> failing_cells(const std::vector<double>& observed, const std::vector<double>& expected,
                               double level);

LiveAnswer samplers_answer(const std::vector<RegisteredSampler>& registry);
LiveAnswer sample_answer(const std::vector<RegisteredSampler>& registry, const LiveQuery& query);

}  // namespace rt::test
