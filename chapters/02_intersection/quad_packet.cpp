#include "quad_packet.hpp"

#include <algorithm>

namespace rt {

QuadPacket make_quad_packet(std::span<const Quad> quads, std::span<const std::uint32_t> indices) {
    QuadPacket packet;
    for (int axis = 0; axis < 3; ++axis) {
        packet.origin[axis] = packet.normal[axis] = packet.a_axis[axis] = packet.b_axis[axis] = 0;
    }
    packet.lanes = int(std::min<std::size_t>(indices.size(), kQuadLanes));
    for (int lane = 0; lane < packet.lanes; ++lane) {
        const Quad& q = quads[indices[std::size_t(lane)]];
        // intersect_quad never hits a degenerate quad (zero axes): a zero normal makes its lane miss too.
        const bool degenerate = q.a_axis == Vec3{0};
        for (int axis = 0; axis < 3; ++axis) {
            packet.origin[axis][lane] = q.origin[axis];
            packet.normal[axis][lane] = degenerate ? Real(0) : q.normal[axis];
            packet.a_axis[axis][lane] = q.a_axis[axis];
            packet.b_axis[axis][lane] = q.b_axis[axis];
        }
        packet.quad[std::size_t(lane)] = indices[std::size_t(lane)];
    }
    return packet;
}

}  // namespace rt
