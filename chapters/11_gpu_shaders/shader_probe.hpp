// The shader's own functions asked directly (shaders/probe.comp), for the tests: the random numbers of a
// (pixel, sample, seed), and the nearest hit of a ray in a flattened scene. Each question is one invocation.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "gl_context.hpp"
#include "gpu_scene.hpp"
#include "rt/core/ray.hpp"

namespace rt {

struct ProbeRandom {
    std::array<std::uint32_t, 4> words;  // the first four next_uint()
    std::array<float, 4> reals;          // the next four next_real()
};

struct ProbeHit {
    bool hit = false;
    float t = 0;
    std::uint32_t primitive = 0;  // in scene order (Hit::primitive)
    bool front_face = false;
    Vec3 normal{0};
    std::uint32_t light = 0;  // the picker's index, 0xFFFFFFFF for none
};

class ShaderProbe {
  public:
    // Compiles probe.comp on `context` (current, outliving the probe) and uploads `scene`.
    ShaderProbe(const GlContext& context, const GpuScene& scene);
    ~ShaderProbe();

    struct Query {
        std::uint64_t pixel, sample;
    };
    std::vector<ProbeRandom> random_numbers(const std::vector<Query>& queries, std::uint64_t seed) const;
    // Each ray's nearest hit with 0 < t < t_max.
    std::vector<ProbeHit> nearest_hits(const std::vector<Ray>& rays, float t_max) const;

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace rt
