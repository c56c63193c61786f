// The spatial half of Practical Path Guiding: a binary tree over the scene's box whose nodes halve their box
// along x, y, z in turn, and whose leaves each own a directional distribution (guiding_field.hpp holds them,
// by the leaf's number). A leaf counts the path vertices recorded in it during a pass; after the pass a leaf
// that counted more than a threshold splits, each half taking half its count, until none exceeds it. Where
// many paths pass, space is cut finely; where few do, a leaf stays large and its distribution still learns
// from enough paths.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "02_intersection/aabb.hpp"
#include "rt/core/math.hpp"

namespace rt {

class SpatialTree {
  public:
    // One leaf (number 0) over `bounds` (a box with some extent along every axis).
    explicit SpatialTree(const Aabb& bounds);

    // The number of the leaf whose box holds p (a point outside the box: the leaf nearest it).
    std::uint32_t leaf_of(const Vec3& p) const;
    // The box of that leaf.
    Aabb leaf_box(const Vec3& p) const;
    // Counts one vertex in `leaf`; safe from several threads at once.
    void count(std::uint32_t leaf);
    std::uint64_t samples(std::uint32_t leaf) const;

    // Splits every leaf that counted more than `threshold` as the header says, and sets every count to 0. A
    // split leaf's first half keeps its number, the second gets the next free one. Returns, for each leaf
    // number after the split, the number of the leaf it was cut from (its own where it was not cut).
    std::vector<std::uint32_t> split(double threshold);

    std::size_t leaf_count() const { return leaf_nodes_.size(); }
    const Aabb& bounds() const { return bounds_; }
    std::size_t bytes() const {
        return sizeof(*this) + nodes_.capacity() * sizeof(Node) +
               leaf_nodes_.capacity() * sizeof(std::uint32_t);
    }

  private:
    struct Node {
        std::uint32_t child = 0;  // the first of its two halves (the second follows it); 0: a leaf
        std::uint32_t leaf = 0;   // a leaf's number
        std::uint64_t samples = 0;
        int axis = 0;  // the axis its halves are cut along
    };
    // The leaf node that holds p; its box in `box` (which starts as bounds_).
    std::uint32_t descend(const Vec3& p, Aabb& box) const;

    Aabb bounds_;
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> leaf_nodes_;  // each leaf's node
};

}  // namespace rt
