// Chapter 02's pictures: each camera ray's nearest hit shown by its normal, its distance, or by what finding
// it cost (boxes plus primitives tested, as a heat map).
#pragma once

#include <optional>

#include <cstdint>

#include "01_ray_generation/camera.hpp"
#include "rt/render/render_loop.hpp"
#include "world.hpp"

namespace rt {

enum class ShowMode { kNormal, kDistance, kCost };

constexpr auto names_of(ShowMode) {
    return enum_names<ShowMode>("--show",
                                {{ShowMode::kNormal, "normal"}, {ShowMode::kDistance, "distance"}, {ShowMode::kCost, "cost"}});
}

// The normal n as the colour (n + 1) / 2.
Color normal_colour(const Vec3& n);
// exp(−t / scale): white near the camera, darker far away.
Color distance_colour(Real t, Real scale);
// A black–blue–red–yellow–white ramp for x in [0, 1].
Color heat_colour(Real x);
// The heat of a query that tested `tests` boxes and primitives: log₂(1 + tests) / 11, white at 2047 tests.
Real cost_heat(std::uint32_t tests);

// Every sample traces one camera ray (stratified in its pixel) and shows its nearest hit; misses are black.
RenderResult render_intersections(const World& world, const PinholeCamera& camera, ShowMode mode,
                                  Real distance_scale, const RenderSettings& settings);

// What finding the nearest hit costs on average: boxes and primitives tested per ray, over one ray through
// each pixel centre (measured apart from the render, so the render counts nothing but rays).
struct MeanTraversalCost {
    double nodes = 0;
    double primitives = 0;
};
// Nothing when an interrupt (Ctrl-C) comes first: it is looked for before every ray, since without a BVH one
// ray may test every primitive of a large mesh.
std::optional<MeanTraversalCost> mean_traversal_cost(const World& world, const PinholeCamera& camera);

}  // namespace rt
