#include "bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace rt {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafSize = 8;
constexpr std::uint32_t kMinSplitCount = 4;
constexpr int kMaxDepth =
    36;  // below it, splits are median splits: the traversal stack of 64 never overflows
// SAH costs, in units of one leaf test (a primitive, or a packet of them): a node visit costs about one.
constexpr double kTraversalCost = 1;

// Half the surface area of a box, in double: float's product of two extents underflows to zero below about
// 1e-23 and overflows above about 1e19, and the SAH divides by it.
double half_area(const Aabb& b) {
    const Vec3d e = glm::max(Vec3d(b.max) - Vec3d(b.min), Vec3d(0));
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

// A centroid that sorts and bins: the midpoint in double (float's min + max can overflow), held within the
// finite Reals; a primitive whose box is unbounded both ways or empty (its centre NaN) counts as at the
// origin, so every comparison stays ordered and every extent finite.
Vec3 centroid_of(const Aabb& b) {
    constexpr double kLargest = std::numeric_limits<Real>::max();
    const Vec3d c = Vec3d(b.min) * 0.5 + Vec3d(b.max) * 0.5;
    Vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = std::isnan(c[i]) ? 0 : Real(std::clamp(c[i], -kLargest, kLargest));
    return out;
}

struct Builder {
    std::span<const Aabb> bounds;
    std::uint32_t leaf_packet;
    std::vector<Vec3> centroids;
    std::vector<std::uint32_t>& indices;
    std::vector<BvhNode>& nodes;

    // The tests a leaf of n primitives costs a ray: ⌈n / leaf_packet⌉.
    double tests(std::uint32_t n) const { return double((n + leaf_packet - 1) / leaf_packet); }

    void make_leaf(std::uint32_t node, std::uint32_t begin, std::uint32_t end) {
        nodes[node].offset = begin;
        nodes[node].count = end - begin;
    }

    // Splits [begin, end) at its middle along `axis` (the fallback when the SAH finds no useful split).
    std::uint32_t median_split(std::uint32_t begin, std::uint32_t end, int axis) {
        const std::uint32_t middle = begin + (end - begin) / 2;
        std::nth_element(
            indices.begin() + begin, indices.begin() + middle, indices.begin() + end,
            [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
        return middle;
    }

    void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth) {
        Aabb box, centroid_box;
        for (std::uint32_t i = begin; i < end; ++i) {
            box.extend(bounds[indices[i]]);
            centroid_box.extend(centroids[indices[i]]);
        }
        nodes[node].min = box.min;
        nodes[node].max = box.max;
        const std::uint32_t count = end - begin;
        // Up to four primitives stay together: splitting them saves a few triangle tests but adds two nodes
        // (64 bytes) and a level to descend; at 10^6 triangles the memory traffic costs more than the tests.
        if (count <= kMinSplitCount) return make_leaf(node, begin, end);
        const int longest = centroid_box.longest_axis();
        const double node_area = half_area(box);
        std::uint32_t middle = 0;
        // In double: a float extent may be subnormal (its inverse infinite) or overflow to infinity (centroids
        // at -3e38 and 3e38), and a float area may underflow to zero or overflow; in double neither can.
        auto extent_of = [&](int axis) { return double(centroid_box.max[axis]) - double(centroid_box.min[axis]); };
        if (!(extent_of(longest) > 0) || !(node_area > 0)) {
            // Every centroid in one point (no plane separates them), or every primitive on one line (the node
            // has no area for the SAH to compare): a leaf, or halves.
            if (count <= kMaxLeafSize) return make_leaf(node, begin, end);
            middle = median_split(begin, end, longest);
        } else if (depth >= kMaxDepth) {
            middle = median_split(begin, end, longest);
        } else {
            // Along each axis, bin the centroids into kBins slabs and evaluate the SAH at each bin boundary:
            // cost(split) = C_trav + (A_left T(N_left) + A_right T(N_right)) / A, against cost(leaf) = T(N),
            // where T(N) = ⌈N / leaf_packet⌉ is the tests N primitives cost. The cheapest split of the three
            // axes is taken.
            // (c − lo) / extent is in [0, 1] for every centroid c of the node: the bin is in [0, kBins).
            auto bin_of = [&](std::uint32_t p, int axis) {
                const double t = (double(centroids[p][axis]) - double(centroid_box.min[axis])) / extent_of(axis) * kBins;
                return t >= kBins - 1 ? kBins - 1 : (t > 0 ? int(t) : 0);
            };
            int best_axis = longest, best = -1;
            double best_cost = std::numeric_limits<double>::infinity();
            for (int axis = 0; axis < 3; ++axis) {
                if (!(extent_of(axis) > 0)) continue;
                std::array<Aabb, kBins> bin_box;
                std::array<std::uint32_t, kBins> bin_count{};
                for (std::uint32_t i = begin; i < end; ++i) {
                    const int b = bin_of(indices[i], axis);
                    ++bin_count[b];
                    bin_box[b].extend(bounds[indices[i]]);
                }
                std::array<double, kBins - 1> left_cost{};
                Aabb left;
                std::uint32_t left_count = 0;
                for (int b = 0; b < kBins - 1; ++b) {
                    left.extend(bin_box[b]);
                    left_count += bin_count[b];
                    left_cost[b] = left_count > 0 ? half_area(left) * tests(left_count) : 0;
                }
                Aabb right;
                std::uint32_t right_count = 0;
                for (int b = kBins - 1; b > 0; --b) {
                    right.extend(bin_box[b]);
                    right_count += bin_count[b];
                    const double cost =
                        left_cost[b - 1] + (right_count > 0 ? half_area(right) * tests(right_count) : 0);
                    if (cost < best_cost) {
                        best_cost = cost;
                        best = b;  // bins [0, b) go left
                        best_axis = axis;
                    }
                }
            }
            const double split_cost = kTraversalCost + best_cost / node_area;
            if (count <= kMaxLeafSize && !(split_cost < tests(count))) return make_leaf(node, begin, end);
            middle = std::uint32_t(std::partition(indices.begin() + begin, indices.begin() + end,
                                                  [&](std::uint32_t p) { return bin_of(p, best_axis) < best; }) -
                                   indices.begin());
            if (middle == begin || middle == end) middle = median_split(begin, end, best_axis);
        }
        const std::uint32_t first = std::uint32_t(nodes.size());
        nodes.push_back({});
        nodes[node].count = 0;
        build(first, begin, middle, depth + 1);
        const std::uint32_t second = std::uint32_t(nodes.size());
        nodes.push_back({});
        nodes[node].offset = second;
        build(second, middle, end, depth + 1);
    }
};

}  // namespace

Bvh::Bvh(std::span<const Aabb> bounds, std::vector<std::uint32_t>& order, std::uint32_t leaf_packet) {
    order.resize(bounds.size());
    std::iota(order.begin(), order.end(), 0u);
    if (bounds.empty()) return;
    Builder builder{bounds, std::max(leaf_packet, 1u), {}, order, nodes_};
    builder.centroids.reserve(bounds.size());
    for (const Aabb& b : bounds) builder.centroids.push_back(centroid_of(b));
    nodes_.reserve(bounds.size());
    nodes_.push_back({});
    builder.build(0, 0, std::uint32_t(bounds.size()), 0);
    nodes_.shrink_to_fit();
}

}  // namespace rt
