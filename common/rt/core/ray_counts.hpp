// Rays traced, counted by kind. Each render thread counts into its own ThreadRayCounts, merged once at the
// end, so counting costs no contention.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace rt {

enum class RayKind { kCamera, kShadow, kReflection, kRefraction, kIndirect };
inline constexpr int kRayKindCount = 5;
inline constexpr std::array<std::string_view, kRayKindCount> kRayKindNames = {"camera", "shadow", "reflection",
                                                                             "refraction", "indirect"};

struct RayCounts {
    std::array<std::uint64_t, kRayKindCount> count{};

    void add(RayKind kind, std::uint64_t n = 1) { count[std::size_t(kind)] += n; }
    std::uint64_t operator[](RayKind kind) const { return count[std::size_t(kind)]; }
    std::uint64_t total() const {
        std::uint64_t sum = 0;
        for (auto c : count) sum += c;
        return sum;
    }
    RayCounts& operator+=(const RayCounts& other) {
        for (std::size_t i = 0; i < count.size(); ++i) count[i] += other.count[i];
        return *this;
    }
};

// One thread's counts, on a cache line of its own: two threads' counts on one line would pass the line
// between their cores at every ray either traces (false sharing).
struct alignas(64) ThreadRayCounts : RayCounts {};

}  // namespace rt
