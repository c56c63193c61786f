#include "guiding_field.hpp"

#include <bit>
#include <cmath>

#include "rt/core/random.hpp"

namespace rt {

GuidingField::GuidingField(const Aabb& bounds, const GuidingSettings& settings)
    : settings_(settings), space_(bounds), guides_(1), recording_(1) {}

const DirectionalQuadtree* GuidingField::guide_at(const Vec3& p) const {
    if (passes_ == 0) return nullptr;
    const DirectionalQuadtree& guide = guides_[space_.leaf_of(p)];
    return guide.energy_units() > 0 ? &guide : nullptr;
}

namespace {

// The bits of a vector's three coordinates, mixed into one number.
std::uint64_t bits_of(const Vec3& v) {
    return std::bit_cast<std::uint64_t>(double(v.x)) * 0x9E3779B97F4A7C15ull ^
           std::bit_cast<std::uint64_t>(double(v.y)) * 0xC2B2AE3D27D4EB4Full ^
           std::bit_cast<std::uint64_t>(double(v.z));
}

}  // namespace

void GuidingField::record(const Vec3& p, const Vec3& wi, Real weight) {
    space_.count(space_.leaf_of(p));
    Vec3 at = p;
    if (settings_.spatial_filter == SpatialFilter::kBox) {
        const Aabb leaf = space_.leaf_box(p);
        Pcg32 rng(bits_of(p), bits_of(wi));
        const Vec3 u(rng.next_real(), rng.next_real(), rng.next_real());
        const Aabb& bounds = space_.bounds();
        at = glm::clamp(p + (u - Real(0.5)) * (leaf.max - leaf.min), bounds.min, bounds.max);
    }
    recording_[space_.leaf_of(at)].record(wi, weight);
}

void GuidingField::finish_pass() {
    const std::vector<std::uint32_t> origin =
        space_.split(settings_.spatial_threshold * std::sqrt(std::ldexp(1.0, passes_)));
    std::vector<DirectionalQuadtree> guides, recording;
    guides.reserve(origin.size());
    recording.reserve(origin.size());
    for (std::uint32_t from : origin) {
        guides.push_back(recording_[from].refined(settings_.energy_threshold, settings_.max_depth));
        recording.push_back(guides.back().emptied());
    }
    guides_ = std::move(guides);
    recording_ = std::move(recording);
    ++passes_;
}

std::size_t GuidingField::bytes() const {
    std::size_t sum = sizeof(*this) + space_.bytes();
    for (const auto* trees : {&guides_, &recording_})
        for (const DirectionalQuadtree& tree : *trees) sum += tree.bytes();
    return sum;
}

Aabb guiding_bounds(const Aabb& scene, const Vec3& camera) {
    Aabb box = scene;
    box.extend(camera);
    const Vec3 margin = Real(0.01) * (box.max - box.min) + Vec3(Real(1e-3));
    box.min -= margin;
    box.max += margin;
    return box;
}

}  // namespace rt
