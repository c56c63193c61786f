#include "bvh.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <experimental/simd>
#include <limits>
#include <thread>

#include "huge_pages.hpp"

namespace rt {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafSize = 8;
constexpr std::uint32_t kMinSplitCount = 4;
constexpr int kMaxDepth =
    36;  // below it, splits are median splits: the traversal stack of 64 never overflows
// SAH costs, in units of one leaf test (a primitive, or a packet of them): a node visit costs about one.
constexpr double kTraversalCost = 1;
// The root builds its second child on a second thread when that child holds at least this many primitives:
// the thread's start (tens of microseconds) is then a small part of the subtree's build.
constexpr std::uint32_t kParallelMinimum = 1 << 14;

namespace stdx = std::experimental;
// A point in one SIMD register: x, y, z and a fourth lane that the build never reads.
using Lanes = stdx::simd<Real, stdx::simd_abi::deduce_t<Real, 4>>;
// The same four in double: where the build bins, in one register on x86-64-v3.
using DoubleLanes = stdx::simd<double, stdx::simd_abi::deduce_t<double, 4>>;
using IntLanes = stdx::simd<int, stdx::simd_abi::deduce_t<int, 4>>;

Vec3 vec3_of(const Lanes& l) {
    return {l[0], l[1], l[2]};
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

// One primitive as the build sees it: ten floats, the lower corner, the centroid, the upper corner and the
// primitive's number (its bits), read four at a time into SIMD registers (x, y, z and a fourth lane holding
// the next member's first float). Only the upper corner's fourth lane is the number, whose bits are a
// subnormal float: the build compares it (max) but computes nothing with it (a subnormal operand costs a
// microcode assist). A node's primitives are a range of these, reordered in place as the nodes are split:
// the build reads them one after another, not through an index into the caller's arrays.
struct Reference {
    std::array<Real, 10> v;

    Reference(const Aabb& b, std::uint32_t primitive) {
        const Vec3 c = centroid_of(b);
        v = {b.min.x, b.min.y, b.min.z, c.x,     c.y,
             c.z,     b.max.x, b.max.y, b.max.z, std::bit_cast<Real>(primitive)};
    }
    std::uint32_t primitive() const { return std::bit_cast<std::uint32_t>(v[9]); }
    Lanes min() const { return Lanes(&v[0], stdx::element_aligned); }
    Lanes centroid() const { return Lanes(&v[3], stdx::element_aligned); }
    Lanes max() const { return Lanes(&v[6], stdx::element_aligned); }
    Real centroid(int axis) const { return v[3 + std::size_t(axis)]; }
};
static_assert(sizeof(Reference) == 40);

// A box as two SIMD registers, grown with two instructions; empty until a box is added.
struct LaneBox {
    Lanes min = kInfinity, max = -kInfinity;

    // glm::min and glm::max lane by lane. (stdx::min and stdx::max carry an attribute of their own, fast
    // math, and GCC then inlines no function that calls them into one that does not.)
    void extend(const Lanes& lo, const Lanes& hi) {
        stdx::where(lo < min, min) = lo;
        stdx::where(max < hi, max) = hi;
    }
    void extend(const LaneBox& b) { extend(b.min, b.max); }
    Aabb aabb() const { return {vec3_of(min), vec3_of(max)}; }
};

// Half the surface area of a box, in double: float's product of two extents underflows to zero below about
// 1e-23 and overflows above about 1e19, and the SAH divides by it.
double half_area(const Aabb& b) {
    const Vec3d e = glm::max(Vec3d(b.max) - Vec3d(b.min), Vec3d(0));
    return e.x * e.y + e.y * e.z + e.z * e.x;
}
double half_area(const LaneBox& b) {
    return half_area(b.aabb());
}

// What the build knows of a set of primitives: the box around them and the box around their centroids.
struct Bounds {
    LaneBox box, centroids;

    void extend(const Reference& r) {
        box.extend(r.min(), r.max());
        const Lanes c = r.centroid();
        centroids.extend(c, c);
    }
};

// The centroids binned into kBins slabs along each axis, in one pass over the node's primitives: each bin's
// primitives counted and boxed.
struct Bins {
    std::array<std::array<LaneBox, kBins>, 3> box;
    std::array<std::array<std::uint32_t, kBins>, 3> count{};
};

// Which of kBins slabs a centroid falls in, along each axis of a node, in double: a float extent may be
// subnormal (its inverse infinite) or overflow to infinity (centroids at -3e38 and 3e38). kBins / extent is
// computed once per node, so a primitive's bin takes a product, not a division; (c − lo) kBins / extent is
// in [0, kBins] (up to rounding) for every centroid of the node: the bin is in [0, kBins). The three axes
// are binned in one register, each lane with the same operations as one axis alone.
struct BinScale {
    DoubleLanes lower = 0, scale = 0;

    explicit BinScale(const Aabb& centroids) {
        for (int axis = 0; axis < 3; ++axis) {
            const double extent = double(centroids.max[axis]) - double(centroids.min[axis]);
            lower[axis] = centroids.min[axis];
            scale[axis] = extent > 0 ? kBins / extent : 0;
        }
    }
    IntLanes bins_of(const Reference& r) const {
        const DoubleLanes t = (DoubleLanes(&r.v[3], stdx::element_aligned) - lower) * scale;
        DoubleLanes bin = t;
        stdx::where(!(t > 0), bin) = 0;
        stdx::where(t >= kBins - 1, bin) = kBins - 1;
        return stdx::static_simd_cast<IntLanes>(bin);
    }
    int bin_of(const Reference& r, int axis) const {
        const double t = (double(r.centroid(axis)) - lower[axis]) * scale[axis];
        return t >= kBins - 1 ? kBins - 1 : (t > 0 ? int(t) : 0);
    }
};

// A split of a node: the bins [0, bin) along `axis` go to the first child.
struct Split {
    int axis = 0;
    int bin = -1;
    double cost = std::numeric_limits<double>::infinity();
};

struct Builder {
    std::uint32_t leaf_packet;
    std::span<Reference> references;
    std::vector<BvhNode> nodes;

    // The tests a leaf of n primitives costs a ray: ⌈n / leaf_packet⌉.
    double tests(std::uint32_t n) const { return double((n + leaf_packet - 1) / leaf_packet); }

    Bounds bounds_of(std::uint32_t begin, std::uint32_t end) const {
        Bounds b;
        for (const Reference& r : references.subspan(begin, end - begin)) b.extend(r);
        return b;
    }

    // Bins [begin, end) by their centroids, in one pass over the node's primitives.
    Bins bin(std::uint32_t begin, std::uint32_t end, const BinScale& scale) const {
        Bins bins;
        for (std::uint32_t i = begin; i < end; ++i) {
            const Reference& r = references[i];
            const IntLanes b = scale.bins_of(r);
            const Lanes lower = r.min(), upper = r.max();
            for (int axis = 0; axis < 3; ++axis) {
                ++bins.count[axis][b[axis]];
                bins.box[axis][b[axis]].extend(lower, upper);
            }
        }
        return bins;
    }

    // The SAH at each bin boundary of each axis whose centroids are spread: cost(split) = C_trav + (A_left
    // T(N_left) + A_right T(N_right)) / A, where T(N) = ⌈N / leaf_packet⌉ is the tests N primitives cost.
    // `cost` is the sum in parentheses; the cheapest boundary of the three axes is taken.
    Split cheapest_split(const Bins& bins, const Aabb& centroids) const {
        Split best;
        for (int axis = 0; axis < 3; ++axis) {
            if (!(double(centroids.max[axis]) - double(centroids.min[axis]) > 0)) continue;
            // An empty bin changes neither side's box nor its count: its costs are its neighbour's.
            std::array<double, kBins - 1> left_cost{};
            LaneBox left;
            std::uint32_t left_count = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                if (bins.count[axis][b] == 0) {
                    left_cost[b] = b > 0 ? left_cost[b - 1] : 0;
                    continue;
                }
                left.extend(bins.box[axis][b]);
                left_count += bins.count[axis][b];
                left_cost[b] = half_area(left) * tests(left_count);
            }
            LaneBox right;
            std::uint32_t right_count = 0;
            for (int b = kBins - 1; b > 0; --b) {
                // Bin b empty, the boundary below it parts the primitives as the one above it did, at the
                // same cost, and only the first of equal costs is taken.
                if (bins.count[axis][b] == 0 && b < kBins - 1) continue;
                if (bins.count[axis][b] > 0) right.extend(bins.box[axis][b]);
                right_count += bins.count[axis][b];
                const double cost =
                    left_cost[b - 1] + (right_count > 0 ? half_area(right) * tests(right_count) : 0);
                if (cost < best.cost) best = {axis, b, cost};
            }
        }
        return best;
    }

    // Splits [begin, end) at its middle along `axis` (the fallback when the SAH finds no useful split).
    std::uint32_t median_split(std::uint32_t begin, std::uint32_t end, int axis) {
        const std::uint32_t middle = begin + (end - begin) / 2;
        std::nth_element(
            references.begin() + begin, references.begin() + middle, references.begin() + end,
            [&](const Reference& a, const Reference& b) { return a.centroid(axis) < b.centroid(axis); });
        return middle;
    }

    void make_leaf(std::uint32_t node, std::uint32_t begin, std::uint32_t end) {
        nodes[node].offset = begin;
        nodes[node].count = end - begin;
    }

    // Builds the subtree of `node` over [begin, end), whose bounds are `bounds`.
    void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth, const Bounds& bounds) {
        const Aabb box = bounds.box.aabb();
        const Aabb centroids = bounds.centroids.aabb();
        nodes[node].min = box.min;
        nodes[node].max = box.max;
        const std::uint32_t count = end - begin;
        // Up to four primitives stay together: splitting them saves a few triangle tests but adds two nodes
        // (64 bytes) and a level to descend; at 10^6 triangles the memory traffic costs more than the tests.
        if (count <= kMinSplitCount) return make_leaf(node, begin, end);
        const int longest = centroids.longest_axis();
        const double node_area = half_area(box);
        const bool spread = double(centroids.max[longest]) - double(centroids.min[longest]) > 0;
        std::uint32_t middle = 0;
        if (!spread || !(node_area > 0)) {
            // Every centroid in one point (no plane separates them), or every primitive on one line (the node
            // has no area for the SAH to compare): a leaf, or halves.
            if (count <= kMaxLeafSize) return make_leaf(node, begin, end);
            middle = median_split(begin, end, longest);
        } else if (depth >= kMaxDepth) {
            middle = median_split(begin, end, longest);
        } else {
            const BinScale scale(centroids);
            const Bins bins = bin(begin, end, scale);
            const Split split = cheapest_split(bins, centroids);
            const double split_cost = kTraversalCost + split.cost / node_area;
            if (count <= kMaxLeafSize && !(split_cost < tests(count))) return make_leaf(node, begin, end);
            Bounds first, second;
            middle = partition(begin, end, split, scale, first, second);
            if (middle != begin && middle != end)
                return split_node(node, begin, middle, end, depth, first, second);
            middle = median_split(begin, end, split.axis);
        }
        split_node(node, begin, middle, end, depth, bounds_of(begin, middle), bounds_of(middle, end));
    }

    // Moves the primitives of [begin, end) whose centroid falls in the split's first bins before the others
    // (std::partition's swaps, in its order) and returns where the second part starts; the two parts' bounds
    // are made in the same pass, each primitive read once rather than partitioned and then read again.
    std::uint32_t partition(std::uint32_t begin, std::uint32_t end, const Split& split, const BinScale& scale,
                            Bounds& first, Bounds& second) {
        auto goes_first = [&](const Reference& r) { return scale.bin_of(r, split.axis) < split.bin; };
        std::uint32_t i = begin, j = end;
        while (true) {
            for (; i < j && goes_first(references[i]); ++i) first.extend(references[i]);
            if (i == j) return i;
            for (--j; i < j && !goes_first(references[j]); --j) second.extend(references[j]);
            if (i == j) {
                second.extend(references[i]);
                return i;
            }
            std::swap(references[i], references[j]);
            first.extend(references[i++]);
            second.extend(references[j]);
        }
    }

    // Makes `node` interior, its children over [begin, middle) and [middle, end), depth first: the first
    // child right after it, the second after the first's subtree. A large second child is built on a thread
    // of its own, into nodes of its own appended after the first's subtree: the same nodes in the same order.
    void split_node(std::uint32_t node, std::uint32_t begin, std::uint32_t middle, std::uint32_t end,
                    int depth, const Bounds& first, const Bounds& second) {
        nodes[node].count = 0;
        std::vector<BvhNode> apart;
        std::jthread second_builder;
        if (depth == 0 && end - middle >= kParallelMinimum) {
            second_builder = std::jthread(
                [&] { apart = build_tree(leaf_packet, references, middle, end, depth + 1, second); });
        }
        const std::uint32_t first_child = std::uint32_t(nodes.size());
        nodes.push_back({});
        build(first_child, begin, middle, depth + 1, first);
        const std::uint32_t second_child = std::uint32_t(nodes.size());
        nodes[node].offset = second_child;
        if (second_builder.joinable()) {
            second_builder.join();
            for (BvhNode n : apart) {
                if (!n.leaf()) n.offset += second_child;
                nodes.push_back(n);
            }
        } else {
            nodes.push_back({});
            build(second_child, middle, end, depth + 1, second);
        }
    }

    // The subtree over references[begin, end), its root first.
    static std::vector<BvhNode> build_tree(std::uint32_t leaf_packet, std::span<Reference> references,
                                           std::uint32_t begin, std::uint32_t end, int depth,
                                           const Bounds& bounds) {
        Builder builder{leaf_packet, references, {}};
        reserve_on_huge_pages(builder.nodes, 2 * std::size_t(end - begin) / kMinSplitCount);
        builder.nodes.push_back({});
        builder.build(0, begin, end, depth, bounds);
        return builder.nodes;
    }
};

}  // namespace

Bvh::Bvh(std::span<const Aabb> bounds, std::vector<std::uint32_t>& order, std::uint32_t leaf_packet)
    : Bvh(
          std::uint32_t(bounds.size()), [&](std::uint32_t i) { return bounds[i]; }, order, leaf_packet) {}

Bvh::Bvh(std::uint32_t n, const std::function<Aabb(std::uint32_t)>& bounds_of,
         std::vector<std::uint32_t>& order, std::uint32_t leaf_packet) {
    order.clear();
    if (n == 0) return;
    std::vector<Reference> references;
    reserve_on_huge_pages(references, n);
    for (std::uint32_t i = 0; i < n; ++i) references.emplace_back(bounds_of(i), i);
    const Builder root{std::max(leaf_packet, 1u), references, {}};
    nodes_ = Builder::build_tree(root.leaf_packet, references, 0, n, 0, root.bounds_of(0, n));
    nodes_.shrink_to_fit();
    reserve_on_huge_pages(order, n);
    for (const Reference& r : references) order.push_back(r.primitive());
}

}  // namespace rt
