// Four quads tested at once. A ray inside a room of big quads (the Cornell box) must test most of its walls:
// there the BVH has little to cull, and the quad test itself is the cost. A QuadPacket holds four quads
// coordinate by coordinate, so that each step of intersect_quad's equations (quad.hpp) runs on all four in
// one SIMD instruction (std::experimental::simd, from GCC's standard library, libstdc++), and one branch asks
// whether any of them is hit. Each lane does intersect_quad's operations in intersect_quad's order, so it
// rounds the same way: the tests check that a packet and intersect_quad give the same hit, bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <experimental/simd>
#include <optional>
#include <span>

#include "quad.hpp"

namespace rt {

inline constexpr int kQuadLanes = 4;
using QuadLanes = std::experimental::fixed_size_simd<Real, kQuadLanes>;

struct QuadPacket {
    // Per coordinate x, y, z: the four quads' origins, unit normals and dual-basis axes (quad.hpp). An unused
    // lane, like a degenerate quad, has a zero normal: its t is ±∞ or NaN, never inside (0, t_max).
    std::array<QuadLanes, 3> origin, normal, a_axis, b_axis;
    std::array<std::uint32_t, kQuadLanes> quad{};  // each lane's quad: its index in the array packed from
    int lanes = 0;                                 // lanes in use, 1 to 4
};

// Packs quads[indices[0..]] (one to four of them) into a packet.
QuadPacket make_quad_packet(std::span<const Quad> quads, std::span<const std::uint32_t> indices);

// The nearest of the packet's quads that the ray hits with t in (0, t_max): its lane, t and (a, b).
struct PacketHit {
    int lane;
    QuadHit hit;
};

// Inline for the reason intersect_quad is.
inline std::optional<PacketHit> intersect_quad_packet(const Ray& ray, const QuadPacket& packet, Real t_max) {
    // EXERCISE(ch02.quad_packet) § Quads four at a time
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    const auto& origin = packet.origin;
    const auto& normal = packet.normal;
    const auto& a_axis = packet.a_axis;
    const auto& b_axis = packet.b_axis;
    // t = n · (Q − o) / (n · d), then q = o + t d − Q, a = q · a_axis, b = q · b_axis, for four quads at
    // once.
    const QuadLanes denominator = normal[0] * d.x + normal[1] * d.y + normal[2] * d.z;
    const QuadLanes to_x = origin[0] - o.x, to_y = origin[1] - o.y, to_z = origin[2] - o.z;
    const QuadLanes t = (normal[0] * to_x + normal[1] * to_y + normal[2] * to_z) / denominator;
    const QuadLanes q_x = (o.x + t * d.x) - origin[0], q_y = (o.y + t * d.y) - origin[1],
                    q_z = (o.z + t * d.z) - origin[2];
    const QuadLanes a = q_x * a_axis[0] + q_y * a_axis[1] + q_z * a_axis[2];
    const QuadLanes b = q_x * b_axis[0] + q_y * b_axis[1] + q_z * b_axis[2];
    const auto hit = t > 0 && t < t_max && a >= 0 && a <= 1 && b >= 0 && b <= 1;
    if (std::experimental::none_of(hit)) return std::nullopt;
    QuadLanes nearest = kInfinity;
    std::experimental::where(hit, nearest) = t;
    const int lane = std::experimental::find_first_set(nearest == std::experimental::hmin(nearest));
    return PacketHit{lane, {t[lane], {a[lane], b[lane]}}};
    // END EXERCISE
}

}  // namespace rt
