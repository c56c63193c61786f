// A bounding volume hierarchy: a binary tree of boxes over the primitives. A ray skips every subtree whose
// box it misses (or meets beyond the nearest hit found so far), so a query visits O(log n) nodes instead of
// testing all n primitives. Built top-down with the binned surface area heuristic (SAH).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "aabb.hpp"

namespace rt {

// 32 bytes in float (two corners and two integers, no padding), in depth-first order: an interior node's
// first child is the node right after it.
struct BvhNode {
    Vec3 min;
    Vec3 max;
    std::uint32_t offset;  // leaf: first slot of its primitives; interior: index of the second child
    std::uint32_t count;   // leaf: number of primitives (> 0); interior: 0

    Aabb box() const { return {min, max}; }
    bool leaf() const { return count > 0; }
};
static_assert(sizeof(BvhNode) == 2 * sizeof(Vec3) + 2 * sizeof(std::uint32_t));

// What a query cost: boxes tested and primitives tested (the heat map of `--show cost`).
struct TraversalStats {
    std::uint32_t nodes = 0;
    std::uint32_t primitives = 0;
};

class Bvh {
  public:
    Bvh() = default;
    // Builds over primitives 0..n−1 with these bounds. The leaves hold slots 0..n−1: slot i is primitive
    // order[i], and the caller stores its primitives in that order, so a leaf's primitives are neighbours
    // in memory (one cache line, not one per primitive). `leaf_packet`: how many of a leaf's primitives one
    // test takes (1: one by one; 4: in packets of four, as the wide BVH's leaves): the SAH weighs a leaf of
    // n primitives as ⌈n / leaf_packet⌉ tests.
    Bvh(std::span<const Aabb> bounds, std::vector<std::uint32_t>& order, std::uint32_t leaf_packet = 1);
    // The same over `count` primitives whose bounds `bounds_of(i)` gives, with no array of them: a World
    // of 10^6 triangles builds without 24 MB of boxes beside the build's own records.
    Bvh(std::uint32_t count, const std::function<Aabb(std::uint32_t)>& bounds_of,
        std::vector<std::uint32_t>& order, std::uint32_t leaf_packet = 1);

    const std::vector<BvhNode>& nodes() const { return nodes_; }
    // The memory the hierarchy adds to the primitives: its nodes.
    std::size_t bytes() const { return nodes_.size() * sizeof(BvhNode); }

    // Visits, nearest box first, every leaf whose box the ray meets before t_max, calling `test(slot, t_max)`
    // for each primitive slot there: it returns true on a hit and then lowers t_max to it.
    // With any_hit, returns at the first hit. Returns whether anything was hit.
    template <typename Test>
    bool traverse(const Ray& ray, const Vec3& inverse_d, Real& t_max, bool any_hit, Test&& test,
                  TraversalStats* stats = nullptr) const;

  private:
    std::vector<BvhNode> nodes_;
};

template <typename Test>
bool Bvh::traverse(const Ray& ray, const Vec3& inverse_d, Real& t_max, bool any_hit, Test&& test,
                   TraversalStats* stats) const {
    // EXERCISE(ch02.bvh_traversal) § Bounding boxes and the BVH
    if (nodes_.empty()) return false;
    if (stats) ++stats->nodes;
    if (slab_entry(nodes_[0].box(), ray, inverse_d, t_max) == kInfinity) return false;
    struct Pending {
        std::uint32_t node;
        Real t_enter;
    };
    Pending stack[64];
    int top = 0;
    std::uint32_t current = 0;
    bool hit = false;
    while (true) {
        const BvhNode& node = nodes_[current];
        if (node.leaf()) {
            for (std::uint32_t slot = node.offset; slot < node.offset + node.count; ++slot) {
                if (stats) ++stats->primitives;
                if (test(slot, t_max)) {
                    hit = true;
                    if (any_hit) return true;
                }
            }
        } else {
            const std::uint32_t first = current + 1;
            const std::uint32_t second = node.offset;
            if (stats) stats->nodes += 2;
            const Real t_first = slab_entry(nodes_[first].box(), ray, inverse_d, t_max);
            const Real t_second = slab_entry(nodes_[second].box(), ray, inverse_d, t_max);
            if (t_first < kInfinity && t_second < kInfinity) {
                const bool first_nearer = t_first <= t_second;
                stack[top++] = first_nearer ? Pending{second, t_second} : Pending{first, t_first};
                current = first_nearer ? first : second;
                continue;
            }
            if (t_first < kInfinity) {
                current = first;
                continue;
            }
            if (t_second < kInfinity) {
                current = second;
                continue;
            }
        }
        // Pop the next subtree that may still hold a nearer hit.
        do {
            if (top == 0) return hit;
            --top;
        } while (stack[top].t_enter > t_max);
        current = stack[top].node;
    }
    // END EXERCISE
}

}  // namespace rt
