#include "wide_bvh.hpp"

#include <cmath>

#include "huge_pages.hpp"

namespace rt {

// Every member given its value at once: a WideRay first made empty and then filled in is cleared by a loop
// of stores (`rep stos`, 112 bytes), which took a tenth of the time the ray's set-up took.
WideRay make_wide_ray(const Ray& ray) {
    const Vec3 inverse = inverse_direction(ray.direction);
    const Vec3& d = ray.direction;
    auto lanes = [](const Vec3& v) { return std::array<BoxLanes, 3>{BoxLanes(v.x), BoxLanes(v.y), BoxLanes(v.z)}; };
    const bool finite =
        std::abs(inverse.x) < kInfinity && std::abs(inverse.y) < kInfinity && std::abs(inverse.z) < kInfinity;
    return {ray, inverse, lanes(ray.origin), lanes(inverse), finite, {int(d.x < 0), int(d.y < 0), int(d.z < 0)}};
}

WideBvh::WideBvh(const Bvh& binary, const LeafItems& leaf_items) {
    if (binary.nodes().empty()) return;
    bounds_ = binary.nodes()[0].box();
    reserve_on_huge_pages(nodes_, binary.nodes().size() / 2 + 1);
    collapse(binary, 0, leaf_items);
    nodes_.shrink_to_fit();
}

// The wide node for binary node `binary_node` (a leaf becomes a node of one child), after which its
// children's subtrees follow, depth first.
std::uint32_t WideBvh::collapse(const Bvh& binary, std::uint32_t binary_node, const LeafItems& leaf_items) {
    const std::vector<BvhNode>& tree = binary.nodes();
    std::array<std::uint32_t, kWideBvhWidth> children{};
    // Each child's surface area, or −1 for a leaf (never opened).
    std::array<Real, kWideBvhWidth> area{};
    int count = 0;
    auto add = [&](int k, std::uint32_t node) {
        children[std::size_t(k)] = node;
        area[std::size_t(k)] = tree[node].leaf() ? Real(-1) : tree[node].box().half_area();
    };
    if (tree[binary_node].leaf()) {
        add(count++, binary_node);
    } else {
        add(count++, binary_node + 1);
        add(count++, tree[binary_node].offset);
    }
    while (count < kWideBvhWidth) {
        // Open the interior child of largest surface area: the one a ray is likeliest to enter (the first of
        // equal areas).
        int widest = -1;
        for (int k = 0; k < count; ++k) {
            if (area[std::size_t(k)] >= 0 && (widest < 0 || area[std::size_t(k)] > area[std::size_t(widest)]))
                widest = k;
        }
        if (widest < 0) break;
        const std::uint32_t opened = children[std::size_t(widest)];
        add(widest, opened + 1);
        add(count++, tree[opened].offset);
    }
    const std::uint32_t index = std::uint32_t(nodes_.size());
    WideBvhNode node;
    for (int k = 0; k < kWideBvhWidth; ++k) {
        const Aabb box = k < count ? tree[children[std::size_t(k)]].box() : Aabb{};
        for (int axis = 0; axis < 3; ++axis) {
            node.corner[0][std::size_t(axis)][std::size_t(k)] = box.min[axis];
            node.corner[1][std::size_t(axis)][std::size_t(k)] = box.max[axis];
        }
        node.child[std::size_t(k)] = node.count[std::size_t(k)] = 0;
    }
    nodes_.push_back(node);
    for (int k = 0; k < count; ++k) {
        const BvhNode& c = tree[children[std::size_t(k)]];
        if (c.leaf()) {
            const ItemRange items = leaf_items ? leaf_items(c) : ItemRange{c.offset, c.count};
            nodes_[index].child[std::size_t(k)] = items.first;
            nodes_[index].count[std::size_t(k)] = items.count;
        } else {
            const std::uint32_t child = collapse(binary, children[std::size_t(k)], leaf_items);
            nodes_[index].child[std::size_t(k)] = child;
        }
    }
    return index;
}

}  // namespace rt
