// A wide BVH: the binary BVH (bvh.hpp) collapsed into a tree whose nodes hold the boxes of up to eight
// children, tested against the ray together in SIMD (std::experimental::simd). A binary tree tests two boxes
// per node, one level per step; an 8-wide tree tests eight per node and has a third of the levels, so a ray
// makes a third of the steps and of the dependent loads from memory, and each step's eight slab tests take
// the instructions of one (AVX: eight floats in a register). The World traces through it; the binary BVH
// stays the one that is built (by the SAH) and the one GPU code and the exercises start from.
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

inline constexpr int kWideBvhWidth = 8;
// Eight Reals in one SIMD register where the machine has one (AVX: eight floats; SSE: two registers), as
// deduce_t picks.
using BoxLanes = std::experimental::simd<Real, std::experimental::simd_abi::deduce_t<Real, kWideBvhWidth>>;

// 256 bytes in float: four cache lines, aligned to them. corner[0][axis][k], corner[1][axis][k]: the lower
// and upper corners of child k's box, coordinate by coordinate, so one aligned load brings one coordinate of
// the eight boxes. An unused child has the empty box (+∞ below, −∞ above), which no ray enters.
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

// What a ray needs for the eight-box slab test, computed once per ray.
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

// slab_entry (aabb.hpp) on the node's eight boxes at once: each box's entry distance on [0, t_max], or +∞
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
    // eight, replaces its interior child of largest surface area by that child's two children.
    explicit WideBvh(const Bvh& binary, const LeafItems& leaf_items = {});

    const std::vector<WideBvhNode>& nodes() const { return nodes_; }
    // The box around everything: the binary root's.
    const Aabb& bounds() const { return bounds_; }
    std::size_t bytes() const { return nodes_.size() * sizeof(WideBvhNode); }

    // What Bvh::traverse does, eight children at a time: visits, nearest box first, every leaf whose box the
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
    // The children still to visit: a node (count 0) or a leaf's items, and the distance at which its box is
    // entered, in three arrays, so that a child is pushed by three stores and no branch. Each level leaves
    // at most seven children pushed, and this tree is no deeper than the binary one: fewer than 70 levels
    // (36 of SAH splits, then median halvings of at most 2^32 primitives).
    constexpr int kStack = (kWideBvhWidth - 1) * 70 + kWideBvhWidth;
    std::uint32_t stack_child[kStack], stack_count[kStack];
    Real stack_t[kStack];
    int top = 0;
    // Which children a ray enters: a coherent ray (a camera's, from outside the scene) takes the same
    // branches as the ray before, which the processor predicts; a ray from inside the scene (a bounce, a
    // shadow ray) seldom does, and its entered children are pushed with no branch.
    const bool gather = any_hit || bounds_.contains(ray.ray.origin);
    std::uint32_t child = 0, count = 0;  // the root
    Real t_enter = 0;
    bool hit = false;
    while (true) {
        if (!(t_enter > t_max)) {  // not entered beyond the nearest hit found since it was pushed
            if (count > 0) {
                if (stats) stats->primitives += count;
                if (test(child, count, t_max)) {
                    hit = true;
                    if (any_hit) return true;
                }
            } else {
                const WideBvhNode& node = nodes_[child];
                const BoxLanes t_lanes = entry_distances(node, ray, t_max);
                if (stats) {
                    for (int k = 0; k < kWideBvhWidth; ++k) stats->nodes += node.used(k);
                }
                alignas(BoxLanes::size() * sizeof(Real)) Real t[kWideBvhWidth];
                t_lanes.copy_to(t, std::experimental::vector_aligned);
                // This node's entered children go to stack[first, top), the last child first, so that the
                // first is on top.
                const int first = top;
                if (gather) {
                    for (int k = kWideBvhWidth - 1; k >= 0; --k) {
                        stack_child[top] = node.child[k];
                        stack_count[top] = node.count[k];
                        stack_t[top] = t[k];
                        top += t[k] < kInfinity;  // written always, kept only if entered
                    }
                } else {
                    for (int k = kWideBvhWidth - 1; k >= 0; --k) {
                        if (!(t[k] < kInfinity)) continue;
                        stack_child[top] = node.child[k];
                        stack_count[top] = node.count[k];
                        stack_t[top++] = t[k];
                    }
                }
                // A nearest-hit query sorts them, nearest on top (a stable sort: the first of equal distances
                // stays above the others); any hit ends an any-hit query, so a nearer one is worth nothing
                // and it keeps them in the node's order.
                if (!any_hit) {
                    for (int i = first + 1; i < top; ++i) {
                        const std::uint32_t c = stack_child[i], n = stack_count[i];
                        const Real d = stack_t[i];
                        int at = i;
                        for (; at > first && stack_t[at - 1] < d; --at) {
                            stack_child[at] = stack_child[at - 1];
                            stack_count[at] = stack_count[at - 1];
                            stack_t[at] = stack_t[at - 1];
                        }
                        stack_child[at] = c;
                        stack_count[at] = n;
                        stack_t[at] = d;
                    }
                }
            }
        }
        if (top == 0) return hit;
        --top;
        child = stack_child[top];
        count = stack_count[top];
        t_enter = stack_t[top];
    }
    // END EXERCISE
}

}  // namespace rt
