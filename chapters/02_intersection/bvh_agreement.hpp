// Whether the BVH answers every ray as testing every primitive does: the same nearest distance, and the same
// occlusion. Used by the BVH's stress tests and its fuzzer (tests/fuzz/bvh_fuzz.cpp) on primitive sets that
// are degenerate, tiny, huge or mixed across scales.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "aabb.hpp"
#include "rt/core/ray.hpp"
#include "rt/core/scene.hpp"

namespace rt {

struct BvhQuery {
    Ray ray;
    Real t_max = kInfinity;
};

// The BVH alone, over boxes as primitives, each hit at its exact entry distance (computed in double, then
// rounded): what it returns, and what the wide BVH collapsed from it returns, must be exactly the
// brute-force minimum, at any scale, since only their culling (the float slab tests) can differ. The first query answered otherwise, in one line; nothing if none.
std::optional<std::string> first_box_disagreement(std::span<const Aabb> boxes, std::span<const BvhQuery> queries);

// A scene of one mesh: triangle i has corners corners[3i], corners[3i + 1], corners[3i + 2] (a trailing
// one or two corners are left out). Nothing is checked: the soup may be degenerate, tiny or huge.
Scene triangle_soup(std::span<const Vec3> corners);

// The first query the World's BVH (the wide one, then the binary one alone) answers differently from the
// brute force, described in one line; nothing when every query agrees. Only distances are compared (two primitives at one distance are a tie), and within the
// rounding bound of each hit (its point_error): the nearest of overlapping coplanar triangles is decided by
// rounding, in the BVH as in the brute force, which test the primitives in different orders.
std::optional<std::string> first_bvh_disagreement(const Scene& scene, std::span<const BvhQuery> queries);

}  // namespace rt
