#include "triangle_packet.hpp"

#include <algorithm>

namespace rt {

TrianglePacket make_triangle_packet(std::span<const Triangle> triangles, std::span<const std::uint32_t> slots) {
    TrianglePacket packet;
    packet.lanes = int(std::min<std::size_t>(triangles.size(), kTriangleLanes));
    for (int lane = 0; lane < kTriangleLanes; ++lane) {
        const std::size_t used = std::size_t(std::min(lane, packet.lanes - 1));
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

}  // namespace rt
