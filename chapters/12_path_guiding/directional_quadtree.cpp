#include "directional_quadtree.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <utility>

#include "equal_area_map.hpp"

namespace rt {

namespace {

// The quadrant of a node's square that holds x (in the node's own [0, 1)²), and x in that quadrant's own
// [0, 1)² (exact: doubling and subtracting 1 are exact in binary floating point).
int quadrant_of(Vec2& x) {
    const int ix = x.x >= Real(0.5), iy = x.y >= Real(0.5);
    x = Real(2) * x - Vec2(Real(ix), Real(iy));
    return ix + 2 * iy;
}

// The four quadrants' energies as weights: uniform where the node has none.
std::array<double, 4> weights_of(const std::array<std::uint64_t, 4>& energy) {
    const std::uint64_t total = energy[0] + energy[1] + energy[2] + energy[3];
    if (total == 0) return {1, 1, 1, 1};
    return {double(energy[0]), double(energy[1]), double(energy[2]), double(energy[3])};
}

}  // namespace

void DirectionalQuadtree::record(Vec2 p, Real weight) {
    if (!(weight >= 0) || !std::isfinite(weight)) return;
    const auto units = std::uint64_t(std::min(double(weight), kMaxRecord) / kEnergyUnit + 0.5);
    if (units == 0) return;
    p = glm::clamp(p, Vec2(0), Vec2(kOneMinusEpsilon));
    for (std::uint32_t node = 0;;) {
        const int q = quadrant_of(p);
        std::atomic_ref<std::uint64_t>(nodes_[node].energy[std::size_t(q)])
            .fetch_add(units, std::memory_order_relaxed);
        node = nodes_[node].child[std::size_t(q)];
        if (node == 0) return;
    }
}

void DirectionalQuadtree::record(const Vec3& w, Real weight) {
    record(equal_area_point(w), weight);
}

std::uint64_t DirectionalQuadtree::energy_units() const {
    const auto& e = nodes_[0].energy;
    return e[0] + e[1] + e[2] + e[3];
}

DirectionalQuadtree DirectionalQuadtree::refined(double threshold, int max_depth) const {
    DirectionalQuadtree out;
    const double total = double(energy_units());
    // Each new node to fill: its place in `out`, its quadrants' energies, the old node that covers the same
    // square (kNone: none, its energies are a split of a leaf's), its level.
    constexpr std::uint32_t kNone = 0xffffffffu;
    struct Task {
        std::uint32_t node;
        std::array<std::uint64_t, 4> energy;
        std::uint32_t old;
        int depth;
    };
    std::vector<Task> tasks{{0, nodes_[0].energy, 0, 1}};
    while (!tasks.empty()) {
        const Task task = tasks.back();
        tasks.pop_back();
        out.nodes_[task.node].energy = task.energy;
        for (std::size_t q = 0; q < 4; ++q) {
            const std::uint64_t e = task.energy[q];
            if (task.depth >= max_depth || !(double(e) > threshold * total)) continue;
            const std::uint32_t old_child = task.old != kNone ? nodes_[task.old].child[q] : 0;
            std::array<std::uint64_t, 4> split{e / 4, e / 4, e / 4, e / 4};
            split[0] += e % 4;
            const auto child = std::uint32_t(out.nodes_.size());
            out.nodes_.emplace_back();
            out.nodes_[task.node].child[q] = child;
            tasks.push_back({child, old_child != 0 ? nodes_[old_child].energy : split,
                             old_child != 0 ? old_child : kNone, task.depth + 1});
        }
    }
    return out;
}

DirectionalQuadtree DirectionalQuadtree::emptied() const {
    DirectionalQuadtree out = *this;
    for (Node& node : out.nodes_) node.energy = {};
    return out;
}

Real DirectionalQuadtree::pdf_square(Vec2 p) const {
    if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)) return 0;
    double pdf = 1;
    for (std::uint32_t node = 0;;) {
        const std::array<double, 4> w = weights_of(nodes_[node].energy);
        const int q = quadrant_of(p);
        pdf *= 4 * w[std::size_t(q)] / (w[0] + w[1] + w[2] + w[3]);
        node = nodes_[node].child[std::size_t(q)];
        if (node == 0 || pdf == 0) return Real(pdf);
    }
}

SquareSample DirectionalQuadtree::sample_square(Vec2 u) const {
    // Down the tree: at each node the column by its share of the energy, then the quadrant in it by its
    // share of the column's, u rescaled to [0, 1)² within the choice each time (in double: twenty levels
    // spend forty bits of it).
    Vec2d x(u), origin(0);
    double size = 1, pdf = 1;
    const auto pick = [](double& v, double p_first) {
        const bool second = !(v < p_first);
        v = second ? (v - p_first) / (1 - p_first) : v / p_first;
        v = std::min(v, 1 - 1e-16);
        return int(second);
    };
    for (std::uint32_t node = 0;;) {
        const std::array<double, 4> w = weights_of(nodes_[node].energy);
        const double total = w[0] + w[1] + w[2] + w[3];
        const int ix = pick(x.x, (w[0] + w[2]) / total);
        const int iy = pick(x.y, w[std::size_t(ix)] / (w[std::size_t(ix)] + w[std::size_t(ix) + 2]));
        const auto q = std::size_t(ix + 2 * iy);
        pdf *= 4 * w[q] / total;
        size /= 2;
        origin += size * Vec2d(ix, iy);
        node = nodes_[node].child[q];
        if (node != 0) continue;
        // The leaf's corners are multiples of 2^-depth, exact in float: the point stays inside its leaf.
        const Vec2 lo(origin), hi(origin + size);
        const Vec2 p(origin + size * x);
        return {{std::clamp(p.x, lo.x, std::nextafter(hi.x, Real(0))),
                 std::clamp(p.y, lo.y, std::nextafter(hi.y, Real(0)))},
                Real(pdf)};
    }
}

Real DirectionalQuadtree::pdf(const Vec3& w) const {
    return pdf_square(equal_area_point(w)) / kEqualAreaJacobian;
}

DirectionSample DirectionalQuadtree::sample(Vec2 u) const {
    const SquareSample s = sample_square(u);
    return {equal_area_direction(s.p), s.pdf / kEqualAreaJacobian};
}

int DirectionalQuadtree::depth() const {
    std::vector<std::pair<std::uint32_t, int>> stack{{0, 1}};
    int deepest = 1;
    while (!stack.empty()) {
        const auto [node, level] = stack.back();
        stack.pop_back();
        deepest = std::max(deepest, level);
        for (std::uint32_t child : nodes_[node].child)
            if (child != 0) stack.push_back({child, level + 1});
    }
    return deepest;
}

}  // namespace rt
