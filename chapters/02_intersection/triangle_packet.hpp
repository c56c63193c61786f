// Four triangles tested at once, as quad_packet.hpp tests four quads. A BVH leaf holds up to four triangles
// that one ray meets in turn; a TrianglePacket holds them coordinate by coordinate, so that each step of the
// watertight test (triangle.cpp, intersect_triangle_watertight) runs on all four in one SIMD instruction
// (std::experimental::simd), and one branch asks whether any of them is hit. Each lane does the scalar
// test's operations in the scalar test's order, so it rounds the same way and stays watertight: the tests
// check that a packet and intersect_triangle_watertight give the same hit, bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <experimental/simd>
#include <optional>
#include <span>

#include "float_error.hpp"
#include "triangle.hpp"

namespace rt {

inline constexpr int kTriangleLanes = 4;
// Four Reals in one SIMD register where the machine has one (SSE: four floats), as deduce_t picks.
using TriangleLanes = std::experimental::simd<Real, std::experimental::simd_abi::deduce_t<Real, kTriangleLanes>>;

struct TrianglePacket {
    // vertex[k][axis]: corner p_k of the four triangles, coordinate by coordinate. An unused lane repeats the
    // last triangle: it gives that triangle's hit again, in a later lane, so the first of equals wins.
    std::array<std::array<TriangleLanes, 3>, 3> vertex;
    std::array<std::uint32_t, kTriangleLanes> slot{};  // each lane's triangle: the caller's number for it
};

// Packs triangles[0..] (one to four of them), lane k numbered slots[k].
TrianglePacket make_triangle_packet(std::span<const Triangle> triangles, std::span<const std::uint32_t> slots);
// The triangle in `lane`, its corners the same floats as the one packed there.
Triangle triangle_in(const TrianglePacket& packet, int lane);

// The nearest of the packet's triangles that the ray hits with t in (δt, t_max): its lane, t and barycentrics.
struct TrianglePacketHit {
    int lane;
    TriangleHit hit;
};

namespace detail {

// (a < b) ? b : a, lane by lane: what std::max does, so that a NaN lane (products overflowing) behaves as in
// the scalar test.
inline TriangleLanes larger(const TriangleLanes& a, const TriangleLanes& b) {
    TriangleLanes out = a;
    std::experimental::where(a < b, out) = b;
    return out;
}

}  // namespace detail

// What the packet test needs of the ray, computed once per ray (make_packet_ray) rather than once per packet:
// the permutation and shear of the watertight test (WatertightRay), and the origin's coordinates in the
// permuted axes, each value in every lane. Read by name, not as ray.origin[s.kx]: glm's operator[] with an
// index known only at run time is a switch, two branches per coordinate, which an incoherent ray (another
// permutation than the ray before) mispredicts.
struct PacketRay {
    int kx, ky, kz;
    TriangleLanes origin_x, origin_y, origin_z;  // o_kx, o_ky, o_kz
    TriangleLanes sx, sy, sz;
};

inline PacketRay make_packet_ray(const Ray& ray, const WatertightRay& s) {
    const Real origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};  // indexed with no branch
    return {s.kx, s.ky, s.kz, origin[s.kx], origin[s.ky], origin[s.kz], s.sx, s.sy, s.sz};
}

// Inline for the reason intersect_quad is (the lesson's "Why intersect_quad lives in its header").
inline std::optional<TrianglePacketHit> intersect_triangle_packet(const PacketRay& s, const TrianglePacket& packet,
                                                                  Real t_max) {
    namespace stdx = std::experimental;
    using L = TriangleLanes;
    const auto& p = packet.vertex;
    // Translate: the vertices relative to the ray's origin, in the permuted axes (kx, ky, kz).
    const L a_x = p[0][s.kx] - s.origin_x, a_y = p[0][s.ky] - s.origin_y, a_z = p[0][s.kz] - s.origin_z;
    const L b_x = p[1][s.kx] - s.origin_x, b_y = p[1][s.ky] - s.origin_y, b_z = p[1][s.kz] - s.origin_z;
    const L c_x = p[2][s.kx] - s.origin_x, c_y = p[2][s.ky] - s.origin_y, c_z = p[2][s.kz] - s.origin_z;
    // Shear: the ray becomes the +z axis.
    const L ax = a_x - s.sx * a_z, ay = a_y - s.sy * a_z;
    const L bx = b_x - s.sx * b_z, by = b_y - s.sy * b_z;
    const L cx = c_x - s.sx * c_z, cy = c_y - s.sy * c_z;
    // Edge functions U, V, W.
    L u = cx * by - cy * bx;
    L v = ax * cy - ay * cx;
    L w = bx * ay - by * ax;
    // A lane with an edge function exactly 0 recomputes all three in double, as the scalar test does.
    const auto zero = u == 0 || v == 0 || w == 0;
    if (stdx::any_of(zero)) {
        for (int k = 0; k < kTriangleLanes; ++k) {
            if (!zero[k]) continue;
            u[k] = Real(double(cx[k]) * double(by[k]) - double(cy[k]) * double(bx[k]));
            v[k] = Real(double(ax[k]) * double(cy[k]) - double(ay[k]) * double(cx[k]));
            w[k] = Real(double(bx[k]) * double(ay[k]) - double(by[k]) * double(ax[k]));
        }
    }
    // The ray passes outside a triangle whose edge functions differ in sign. Most packets a ray reaches are
    // missed this way, and return before the distance is computed.
    const auto outside = (u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0);
    if (stdx::all_of(outside)) return std::nullopt;
    const L det = u + v + w;
    const L az = s.sz * a_z, bz = s.sz * b_z, cz = s.sz * c_z;
    const L t_scaled = u * az + v * bz + w * cz;
    const L t_limit = t_max * det;
    const auto beyond = (det < 0 && (t_scaled >= 0 || t_scaled < t_limit)) ||
                        (det >= 0 && (t_scaled <= 0 || t_scaled > t_limit));
    // A lane whose T may have been rounded among subnormals is decided in double, as in the scalar test.
    const auto in_double = stdx::abs(t_scaled) < kSmallestScaledDistance;
    // det == 0: the ray lies in the triangle's plane, or the triangle is degenerate; no hit.
    const auto candidate = !outside && det != 0 && (!beyond || in_double);
    if (stdx::none_of(candidate)) return std::nullopt;
    const L inverse = Real(1) / det;
    L t = t_scaled * inverse;
    // t is accepted only beyond the bound δt on its rounding error (PBRT 4 §6.8.7), as in the scalar test.
    const L max_z = detail::larger(detail::larger(stdx::abs(az), stdx::abs(bz)), stdx::abs(cz));
    const L max_x = detail::larger(detail::larger(stdx::abs(ax), stdx::abs(bx)), stdx::abs(cx));
    const L max_y = detail::larger(detail::larger(stdx::abs(ay), stdx::abs(by)), stdx::abs(cy));
    const L max_e = detail::larger(detail::larger(stdx::abs(u), stdx::abs(v)), stdx::abs(w));
    const L delta_t = watertight_distance_bound(max_x, max_y, max_z, max_e, stdx::abs(inverse));
    auto hit = candidate && !in_double && t > delta_t && t < t_max;
    if (stdx::any_of(candidate && in_double)) {
        for (int k = 0; k < kTriangleLanes; ++k) {
            if (!candidate[k] || !in_double[k]) continue;
            const auto lane = watertight_hit_in_double({u[k], v[k], w[k]}, {ax[k], bx[k], cx[k]},
                                                       {ay[k], by[k], cy[k]}, {az[k], bz[k], cz[k]}, t_max);
            hit[k] = lane.has_value();
            if (lane) t[k] = lane->t;
        }
    }
    if (stdx::none_of(hit)) return std::nullopt;
    // The nearest hit lane; the first of equals, as a scalar loop over the lanes would keep.
    L nearest = kInfinity;
    stdx::where(hit, nearest) = t;
    const int lane = stdx::find_first_set(hit && nearest == stdx::hmin(nearest));
    return TrianglePacketHit{lane, {t[lane], {v[lane] * inverse[lane], w[lane] * inverse[lane]}}};
}

// The same for one ray alone (the tests): its PacketRay made on the spot.
inline std::optional<TrianglePacketHit> intersect_triangle_packet(const Ray& ray, const WatertightRay& s,
                                                                  const TrianglePacket& packet, Real t_max) {
    return intersect_triangle_packet(make_packet_ray(ray, s), packet, t_max);
}

}  // namespace rt
