#include "triangle_packet.hpp"

#include <algorithm>

namespace rt {

TrianglePacket make_triangle_packet(std::span<const Triangle> triangles, std::span<const std::uint32_t> slots) {
    TrianglePacket packet;
    const int lanes = int(std::min<std::size_t>(triangles.size(), kTriangleLanes));
    for (int lane = 0; lane < kTriangleLanes; ++lane) {
        const std::size_t used = std::size_t(std::min(lane, lanes - 1));
        const Triangle& t = triangles[used];
        for (int axis = 0; axis < 3; ++axis) {
            packet.vertex[0][axis][lane] = t.p0[axis];
            packet.vertex[1][axis][lane] = t.p1[axis];
            packet.vertex[2][axis][lane] = t.p2[axis];
        }
        packet.slot[std::size_t(lane)] = slots[used];
    }
    return packet;
}

Triangle triangle_in(const TrianglePacket& packet, int lane) {
    auto corner = [&](int k) {
        const auto& v = packet.vertex[std::size_t(k)];
        return Vec3{v[0][lane], v[1][lane], v[2][lane]};
    };
    return {corner(0), corner(1), corner(2)};
}

}  // namespace rt
