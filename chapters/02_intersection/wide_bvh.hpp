// A wide BVH: the binary BVH (bvh.hpp) collapsed into a tree whose nodes hold the boxes of up to four
// children, tested against the ray together in SIMD (std::experimental::simd). A binary tree tests two boxes
// per node, one level per step; a 4-wide tree tests four per node and has half the levels, so a ray makes
// half the steps and half the dependent loads from memory, and each step's four slab tests take the
// instructions of one. The World traces through it; the binary BVH stays the one that is built (by the SAH)
// and the one GPU code and the exercises start from.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <experimental/simd>
#include <functional>
#include <vector>

#include "aabb.hpp"
#include "bvh.hpp"

namespace rt {

inline constexpr int kWideBvhWidth = 4;
// Four Reals in one SIMD register where the machine has one (SSE: four floats), as deduce_t picks.
using BoxLanes = std::experimental::simd<Real, std::experimental::simd_abi::deduce_t<Real, kWideBvhWidth>>;

// 128 bytes in float: two cache lines, aligned to them. corner[0][axis][k], corner[1][axis][k]: the lower
// and upper corners of child k's box, coordinate by coordinate, so one aligned load brings one coordinate of
// the four boxes. An unused child has the empty box (+∞ below, −∞ above), which no ray enters.
struct alignas(64) WideBvhNode {
    using Coordinates = std::array<Real, kWideBvhWidth>;
    alignas(BoxLanes::size() * sizeof(Real)) std::array<std::array<Coordinates, 3>, 2> corner;
    std::array<std::uint32_t, kWideBvhWidth> child;  // interior child: its node; leaf: its first item
    std::array<std::uint32_t, kWideBvhWidth> count;  // leaf: its items (> 0); interior or unused: 0

    Aabb box(int k) const {
        const auto& [lower, upper] = corner;
        return {{lower[0][k], lower[1][k], lower[2][k]}, {upper[0][k], upper[1][k], upper[2][k]}};
    }
    bool used(int k) const { return corner[0][0][k] <= corner[1][0][k]; }
};

// What a ray needs for the four-box slab test, computed once per ray.
struct WideRay {
    Ray ray;
    Vec3 inverse_d;
    std::array<BoxLanes, 3> origin, inverse;  // o_i and 1 / d_i in every lane
    bool finite;                              // every 1 / d_i finite: the SIMD test applies
    // The corner whose face the ray enters slab i by: 0 (lower) when d_i >= 0, 1 (upper) when d_i < 0; it
    // leaves by the other. An index, not a branch: the walk loads corner[near_corner[i]] with no jump to mispredict.
    std::array<int, 3> near_corner;
};


WideRay make_wide_ray(const Ray& ray);

// slab_entry (aabb.hpp) on the node's four boxes at once: each box's entry distance on [0, t_max], or +∞
// where the ray misses it. With every 1 / d_i finite, the slab along i is entered at the lower face when
// d_i > 0 and the upper one when d_i < 0 (ordering by the direction's sign replaces slab_entry's swap), and
// each lane does slab_entry's operations in its order, with its conservative widening of entry and exit:
// the same distances, bit for bit. A ray with a zero or subnormal d_i
// takes slab_entry itself, box by box.
inline BoxLanes entry_distances(const WideBvhNode& node, const WideRay& r, Real t_max) {
    namespace stdx = std::experimental;
    if (!r.finite) {
        // An unused child is skipped: slab_entry's double-precision branch would order the empty box's
        // infinite faces and enter it.
        BoxLanes t = kInfinity;
        for (int k = 0; k < kWideBvhWidth; ++k) {
            if (node.used(k)) t[k] = slab_entry(node.box(k), r.ray, r.inverse_d, t_max);
        }
        return t;
    }
    // The nearest exit and the farthest entry of the three slabs, as they are computed; the rounding
    // margins are applied once, after the max and the min: each widening is a rounded monotone function, so
    // max_i of it is it of max_i, bit for bit (and min alike).
    BoxLanes t_near_max = 0, t_far_min = kInfinity;
    for (int i = 0; i < 3; ++i) {
        const auto& near = node.corner[r.near_corner[i]][i];
        const auto& far = node.corner[1 - r.near_corner[i]][i];
        const BoxLanes t_near = (BoxLanes(near.data(), stdx::vector_aligned) - r.origin[i]) * r.inverse[i];
        const BoxLanes t_far = (BoxLanes(far.data(), stdx::vector_aligned) - r.origin[i]) * r.inverse[i];
        t_near_max = i == 0 ? t_near : stdx::max(t_near_max, t_near);
        t_far_min = i == 0 ? t_far : stdx::min(t_far_min, t_far);
    }
    widen_slab(t_near_max, t_far_min);
    const BoxLanes t_enter = stdx::max(BoxLanes(0), t_near_max);
    const BoxLanes t_exit = stdx::min(BoxLanes(t_max), t_far_min);
    BoxLanes entered = t_enter;
    stdx::where(!(t_enter <= t_exit), entered) = kInfinity;
    return entered;
}

class WideBvh {
  public:
    // What a leaf of the binary BVH becomes: its items, [first, first + count). By default its primitive
    // slots themselves; the World maps each leaf to its packets and other primitives.
    struct ItemRange {
        std::uint32_t first;
        std::uint32_t count;
    };
    using LeafItems = std::function<ItemRange(const BvhNode& leaf)>;

    WideBvh() = default;
    // Collapses `binary`: each wide node takes a binary node's two children and, while it has fewer than
    // four, replaces its interior child of largest surface area by that child's two children.
    explicit WideBvh(const Bvh& binary, const LeafItems& leaf_items = {});

    const std::vector<WideBvhNode>& nodes() const { return nodes_; }
    // The box around everything: the binary root's.
    const Aabb& bounds() const { return bounds_; }
    std::size_t bytes() const { return nodes_.size() * sizeof(WideBvhNode); }

    // What Bvh::traverse does, four children at a time: visits, nearest box first, every leaf whose box the
    // ray meets before t_max, calling `test(first, count, t_max)` for its items; it returns true on a hit
    // and then lowers t_max. With any_hit, returns at the first hit. Returns whether anything was hit.
    // A ray starting outside bounds() (a camera's) picks the children it enters by a branch per child, one
    // starting inside (a bounce, a shadow ray) and an any-hit query without a branch: the same children, in
    // the same order.
    template <typename Test>
    bool traverse(const WideRay& ray, Real& t_max, bool any_hit, Test&& test,
                  TraversalStats* stats = nullptr) const;

  private:
    std::uint32_t collapse(const Bvh& binary, std::uint32_t binary_node, const LeafItems& leaf_items);

    std::vector<WideBvhNode> nodes_;
    Aabb bounds_;
};

template <typename Test>
bool WideBvh::traverse(const WideRay& ray, Real& t_max, bool any_hit, Test&& test, TraversalStats* stats) const {
    // EXERCISE(ch02.wide_bvh_traversal) § Which tree draws the picture, and the exercise wide_bvh_traversal
    if (nodes_.empty()) return false;
    // A child still to visit: a node (count 0) or a leaf's items, and the distance at which its box is entered.
    struct Pending {
        std::uint32_t child;
        std::uint32_t count;
        Real t_enter;
    };
    // Each level leaves at most three children pushed, and this tree is no deeper than the binary one: fewer
    // than 70 levels (36 of SAH splits, then median halvings of at most 2^32 primitives).
    Pending stack[3 * 70 + 1];
    int top = 0;
    // Which children a ray enters, node after node: a coherent ray (a camera's, from outside the scene)
    // takes the same branches as the ray before, and the processor, predicting them, loads the next node
    // before this one's test is done. A ray from inside the scene (a bounce, a shadow ray) is seldom
    // coherent with the one before, and a branch per child, entered or not, is often mispredicted: its
    // entered children are gathered with no branch.
    const bool gather = any_hit || bounds_.contains(ray.ray.origin);
    Pending next{0, 0, 0};  // the root
    bool hit = false;
    while (true) {
        if (!(next.t_enter > t_max)) {  // not entered beyond the nearest hit found since it was pushed
            if (next.count > 0) {
                if (stats) stats->primitives += next.count;
                if (test(next.child, next.count, t_max)) {
                    hit = true;
                    if (any_hit) return true;
                }
            } else {
                const WideBvhNode& node = nodes_[next.child];
                const BoxLanes t_lanes = entry_distances(node, ray, t_max);
                if (stats) {
                    for (int k = 0; k < kWideBvhWidth; ++k) stats->nodes += node.used(k);
                }
                alignas(BoxLanes::size() * sizeof(Real)) Real t[kWideBvhWidth];
                t_lanes.copy_to(t, std::experimental::vector_aligned);
                Pending entered[kWideBvhWidth];
                int n = 0;
                // Places p among entered[0, at), nearest first (the first of equal distances first).
                auto insert = [&](Pending p, int at) {
                    for (; at > 0 && entered[at - 1].t_enter > p.t_enter; --at) entered[at] = entered[at - 1];
                    entered[at] = p;
                };
                if (gather) {
                    // Each child is written to the next place and kept by n += entered, with no branch.
                    for (int k = 0; k < kWideBvhWidth; ++k) {
                        entered[n] = {node.child[k], node.count[k], t[k]};
                        // Every interior child's node asked for early, entered or not: choosing by `entered`
                        // too cost more than it saved. A leaf asks for this node again, already here (a choice
                        // of address, not a branch).
                        const std::uint32_t ask = node.count[k] == 0 ? node.child[k] : next.child;
                        __builtin_prefetch(&nodes_[ask]);
                        __builtin_prefetch(reinterpret_cast<const char*>(&nodes_[ask]) + 64);
                        n += t[k] < kInfinity;
                    }
                    // An any-hit query keeps them in their order: any hit ends it, so a nearer one is worth
                    // nothing. A nearest-hit query sorts them.
                    if (!any_hit) {
                        for (int i = 1; i < n; ++i) insert(entered[i], i);
                    }
                } else {
                    // The children entered, each put in its place as it is found.
                    for (int k = 0; k < kWideBvhWidth; ++k) {
                        if (!(t[k] < kInfinity)) continue;
                        const Pending p{node.child[k], node.count[k], t[k]};
                        if (p.count == 0) {
                            __builtin_prefetch(&nodes_[p.child]);
                            __builtin_prefetch(reinterpret_cast<const char*>(&nodes_[p.child]) + 64);
                        }
                        insert(p, n++);
                    }
                }
                // The nearest (or first) is visited next, the others pushed farthest (or last) first.
                if (n > 0) {
                    while (n > 1) stack[top++] = entered[--n];
                    next = entered[0];
                    continue;
                }
            }
        }
        if (top == 0) return hit;
        next = stack[--top];
    }
    // END EXERCISE
}

}  // namespace rt
