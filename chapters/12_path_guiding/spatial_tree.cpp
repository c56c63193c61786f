#include "spatial_tree.hpp"

#include <atomic>

namespace rt {

SpatialTree::SpatialTree(const Aabb& bounds) : bounds_(bounds), nodes_(1), leaf_nodes_{0} {}

std::uint32_t SpatialTree::descend(const Vec3& p, Aabb& box) const {
    box = bounds_;
    std::uint32_t node = 0;
    while (nodes_[node].child != 0) {
        const int axis = nodes_[node].axis;
        const Real middle = (box.min[axis] + box.max[axis]) / 2;
        const bool second = p[axis] >= middle;
        (second ? box.min : box.max)[axis] = middle;
        node = nodes_[node].child + std::uint32_t(second);
    }
    return node;
}

std::uint32_t SpatialTree::leaf_of(const Vec3& p) const {
    Aabb box;
    return nodes_[descend(p, box)].leaf;
}

Aabb SpatialTree::leaf_box(const Vec3& p) const {
    Aabb box;
    descend(p, box);
    return box;
}

void SpatialTree::count(std::uint32_t leaf) {
    std::atomic_ref<std::uint64_t>(nodes_[leaf_nodes_[leaf]].samples).fetch_add(1, std::memory_order_relaxed);
}

std::uint64_t SpatialTree::samples(std::uint32_t leaf) const {
    return nodes_[leaf_nodes_[leaf]].samples;
}

std::vector<std::uint32_t> SpatialTree::split(double threshold) {
    std::vector<std::uint32_t> origin(leaf_nodes_.size());
    for (std::uint32_t leaf = 0; leaf < origin.size(); ++leaf) origin[leaf] = leaf;
    // The leaves to look at, as node numbers; a split adds its two halves.
    std::vector<std::uint32_t> pending(leaf_nodes_.begin(), leaf_nodes_.end());
    while (!pending.empty()) {
        const std::uint32_t node = pending.back();
        pending.pop_back();
        const Node parent = nodes_[node];
        if (!(double(parent.samples) > threshold)) continue;
        const auto first = std::uint32_t(nodes_.size());
        const int axis = (parent.axis + 1) % 3;
        const std::uint64_t half = parent.samples / 2;
        const auto second_leaf = std::uint32_t(leaf_nodes_.size());
        nodes_.push_back({0, parent.leaf, half, axis});
        nodes_.push_back({0, second_leaf, parent.samples - half, axis});
        nodes_[node].child = first;
        leaf_nodes_[parent.leaf] = first;
        leaf_nodes_.push_back(first + 1);
        origin.push_back(origin[parent.leaf]);
        pending.push_back(first);
        pending.push_back(first + 1);
    }
    for (Node& node : nodes_) node.samples = 0;
    return origin;
}

}  // namespace rt
