// The furnace: the camera inside a closed box whose walls are all diffuse of albedo ρ and all emit Le. Every
// point then sends the same radiance L in every direction, and the rendering equation becomes one number:
//   L = Le + ∫ (ρ / π) L cos θ dω = Le + ρ L,   so   L = Le / (1 − ρ)   (ρ < 1)
// Expanded bounce by bounce, L = Le (1 + ρ + ρ² + ...): light that bounced k times contributes Le ρ^k, and
// a path cut after N bounces sees the partial sum
//   L_N = Le (1 − ρ^(N+1)) / (1 − ρ),   with bias L_N − L = −Le ρ^(N+1) / (1 − ρ).
// An exact answer for every pixel, so a termination rule's bias and error can be measured.
#pragma once

#include <optional>

#include "02_intersection/world.hpp"
#include "rt/core/image.hpp"
#include "rt/core/scene.hpp"

namespace rt {

struct Furnace {
    Color albedo{0.8f};    // ρ, every channel in [0, 1)
    Color emission{1.0f};  // Le
};

// L = Le / (1 − ρ), per channel, in double.
Vec3d furnace_radiance(const Furnace& furnace);
// L_N = Le (1 − ρ^(N+1)) / (1 − ρ), per channel, in double: the expected value with at most N bounces.
Vec3d furnace_radiance_truncated(const Furnace& furnace, int bounces);

// The furnace's box: the cube [−1, 1]³ as six quads facing inward (their emitting side), the camera at
// `eye` inside, looking at `at`.
Scene make_furnace_scene(const Furnace& furnace, const Vec3& eye = Vec3(0), const Vec3& at = {0, 0, -1});

// The scene's furnace when it is one: every shape has the same diffuse, emissive material of albedo < 1,
// there is no point or environment light, and 1000 rays from the camera in all directions each hit the front
// (emitting) side of a shape. Nothing otherwise.
std::optional<Furnace> find_furnace(const Scene& scene, const World& world);

// An image of the given size, every pixel L = Le / (1 − ρ).
Image furnace_image(const Furnace& furnace, int width, int height);

}  // namespace rt
