// The directional quadtree of Practical Path Guiding (Müller, Gross and Novák 2017): a distribution over the
// sphere learned from the light paths carried, stored on the unit square of the equal-area map
// (equal_area_map.hpp). Each node splits its square into four quadrants and keeps the energy recorded in
// each; a quadrant is a leaf or has a node of its own. The density at a point is Π 4 e_q / Σ e over the
// quadrants on the way down to it: proportional to the energy per area of its leaf, so sampling by descent
// (one quadrant per level, chosen by energy) draws exactly that density. Refining splits the quadrants that
// hold more than a share of the energy and merges the others, so the leaves follow where the light is.
// Energies are fixed-point integers added atomically: several threads may record at once, and the sums do not
// depend on the order they arrive in (the image is the same on any number of threads).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rt/core/math.hpp"

namespace rt {

// A point of the square drawn from the tree, and its density on the square.
struct SquareSample {
    Vec2 p{0};
    Real pdf = 0;
};

// A direction drawn from the tree, and its density per steradian.
struct DirectionSample {
    Vec3 w{0, 0, 1};
    Real pdf = 0;
};

class DirectionalQuadtree {
  public:
    // Recorded weight w adds round(w / kEnergyUnit) units; a weight above kMaxRecord counts as kMaxRecord
    // (the distribution only guides: a capped firefly biases no image).
    static constexpr double kEnergyUnit = 1.0 / 65536;
    static constexpr double kMaxRecord = 1 << 20;

    // One node, its four quadrants leaves without energy: the uniform density.
    DirectionalQuadtree() : nodes_(1) {}

    // Adds `weight` (≥ 0; anything else is ignored) to the quadrant holding p at every level. Safe from
    // several threads at once.
    void record(Vec2 p, Real weight);
    void record(const Vec3& w, Real weight);

    // The energy recorded, in units of kEnergyUnit, and in units of weight.
    std::uint64_t energy_units() const;
    double energy() const { return double(energy_units()) * kEnergyUnit; }

    // A tree whose quadrants split where their share of the energy exceeds `threshold`, down to `max_depth`
    // levels (the root's quadrants are level 1), and are leaves elsewhere. It keeps the energy: a new split
    // divides its quadrant's energy in four (the remainder to the first), so the density is the same but for
    // that rounding, and the total is the same to the unit.
    DirectionalQuadtree refined(double threshold, int max_depth) const;
    // The same quadrants without energy: where the next pass records.
    DirectionalQuadtree emptied() const;

    // The density on the square, and a point drawn from it with u in [0, 1)².
    Real pdf_square(Vec2 p) const;
    SquareSample sample_square(Vec2 u) const;
    // The same on the sphere: the square's density divided by the Jacobian 4π.
    Real pdf(const Vec3& w) const;
    DirectionSample sample(Vec2 u) const;

    std::size_t node_count() const { return nodes_.size(); }
    // The levels of the deepest quadrant.
    int depth() const;
    std::size_t bytes() const { return sizeof(*this) + nodes_.capacity() * sizeof(Node); }

  private:
    struct Node {
        std::array<std::uint32_t, 4> child{};   // the quadrant's node; 0: a leaf (the root is no child)
        std::array<std::uint64_t, 4> energy{};  // quadrant q = x half + 2 × y half
    };
    std::vector<Node> nodes_;
};

}  // namespace rt
