// The guiding distribution of a scene: the spatial tree (spatial_tree.hpp) and, in each of its leaves, two
// directional quadtrees (directional_quadtree.hpp): the guide, learned in the passes before, which paths
// sample from, and the one the current pass records into. Training runs in passes (Practical Path Guiding,
// § 4): after pass k the leaves that counted more than c √(2^k) vertices split (each half starts from its
// parent's trees), every recorded quadtree is refined by its own energy and becomes the guide, and an empty
// copy of it records the next pass. Each pass thus learns from paths that the previous one already guided.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "02_intersection/aabb.hpp"
#include "directional_quadtree.hpp"
#include "rt/core/enum_names.hpp"
#include "spatial_tree.hpp"

namespace rt {

// Where a record lands in space.
enum class SpatialFilter {
    kNearest,  // the leaf that holds the vertex
    kBox,      // the leaf that holds a point drawn uniformly from a box of the vertex's leaf's size about it
};

constexpr auto names_of(SpatialFilter) {
    return enum_names<SpatialFilter>("--spatial-filter",
                                     {{SpatialFilter::kNearest, "nearest"}, {SpatialFilter::kBox, "box"}});
}

struct GuidingSettings {
    double spatial_threshold = 12000;  // c: a leaf splits after pass k past c √(2^k) vertices (the paper's)
    double energy_threshold = 0.01;    // ρ: a quadrant splits past this share of its tree's energy
    int max_depth = 20;                // the quadtrees' deepest level
    Real guided_fraction = Real(0.1);  // α: the chance a guided vertex draws from the guide (measured: § 7)
    SpatialFilter spatial_filter = SpatialFilter::kNearest;
};

class GuidingField {
  public:
    GuidingField(const Aabb& bounds, const GuidingSettings& settings);

    // The guide at p: the leaf's distribution of the passes before, or null where they learned nothing (no
    // pass finished, or no energy recorded in the leaf).
    const DirectionalQuadtree* guide_at(const Vec3& p) const;
    // Records a vertex at p: light of weight `weight` (radiance over the density it was drawn with) arrived
    // from direction wi. Safe from several threads at once, and the sums do not depend on their order. The
    // vertex counts in p's leaf; under SpatialFilter::kBox its light lands in the leaf of a point drawn about
    // p (Müller's stochastic box filter, 2019: a leaf learns from the vertices near it too, and neighbouring
    // guides blend at their border), the point's numbers a hash of p and wi (the same on any thread).
    void record(const Vec3& p, const Vec3& wi, Real weight);
    // Ends a pass as the header says.
    void finish_pass();

    const GuidingSettings& settings() const { return settings_; }
    int passes() const { return passes_; }
    std::size_t leaf_count() const { return space_.leaf_count(); }
    // The memory of the trees: the spatial tree and every leaf's two quadtrees.
    std::size_t bytes() const;

  private:
    GuidingSettings settings_;
    SpatialTree space_;
    std::vector<DirectionalQuadtree> guides_, recording_;  // by leaf
    int passes_ = 0;
};

// The box guiding learns over: the scene's (its BVH's root) and the camera's position, a little larger, with
// some extent along every axis.
Aabb guiding_bounds(const Aabb& scene, const Vec3& camera);

}  // namespace rt
