// The irradiance integral E(p) = ∫ L(wi) cos θ dω at a point p with normal n = +z, estimated with each
// sampling strategy from N samples and checked against chapter 04's closed forms. One sample's estimate:
//   uniform: L cos θ / (1 / 2π)       cosine (= brdf for E): L cos θ / (cos θ / π) = π L
//   light:   L cos θ / pdf_light       mis:     w_l L cos θ / p_l + w_c π L   (one of each, power heuristic)
// The mean of N estimates has expectation E and variance σ² / N, so its error falls like 1 / √N; the
// efficiency of an estimator is 1 / (σ² × time per sample).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "04_direct_lighting/area_lights.hpp"
#include "rt/core/scene.hpp"
#include "sample_stream.hpp"
#include "sampling_strategy.hpp"

namespace rt {

// One emitter over p = 0 with n = +z: a quad light, a sphere light or a uniform sky, of radiance 1.
struct IrradianceCase {
    std::string name;
    // Exactly one of: a quad, a sphere, an environment.
    std::optional<QuadLight> quad;
    std::optional<SphereLight> sphere;
    std::optional<EnvironmentLight> environment;
    double exact = 0;  // E from the closed form (Lambert's polygon formula, π (r/d)² cos θ, π L)
};

// The three cases of the lesson: a 1×1 quad light at height 1 off to one side, a sphere of radius 0.5 at
// distance √4.25 above the horizon, and the sky.
std::vector<IrradianceCase> irradiance_cases();

struct IrradianceEstimate {
    double mean = 0;            // (1/N) Σ estimates
    double variance = 0;        // σ², the variance of one sample's estimate
    double standard_error = 0;  // σ / √N
    double seconds = 0;         // time for the N samples
};

// N samples with `strategy`, their points of [0, 1)² from `points` (sample_stream.hpp): independent (Pcg32),
// stratified (point j in cell j of an m×m grid, m = ⌊√N⌋, the rest independent) or Sobol (the
// Owen-scrambled points of owen_sobol.hpp, dimensions 2 and 3 for MIS's second point). The same seed gives
// the same estimate.
IrradianceEstimate estimate_irradiance(const IrradianceCase& c, SamplingStrategy strategy, int samples,
                                       std::uint64_t seed, PointSet points = PointSet::kIndependent);

}  // namespace rt
