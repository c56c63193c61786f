#include "box.hpp"

#include <utility>

namespace rt {

std::array<Quad, 6> box_faces(const BoxShape& box) {
    auto corner = [&](int x, int y, int z) {
        return box.transform.apply_to_point(
            {x ? box.max.x : box.min.x, y ? box.max.y : box.min.y, z ? box.max.z : box.min.z});
    };
    const Vec3 center = box.transform.apply_to_point((box.min + box.max) * Real(0.5));
    std::array<Quad, 6> faces;
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            std::array<int, 3> o{0, 0, 0}, a{0, 0, 0}, b{0, 0, 0};
            o[axis] = a[axis] = b[axis] = side;
            a[(axis + 1) % 3] = 1;
            b[(axis + 2) % 3] = 1;
            const Vec3 origin = corner(o[0], o[1], o[2]);
            Vec3 u = corner(a[0], a[1], a[2]) - origin;
            Vec3 v = corner(b[0], b[1], b[2]) - origin;
            if (glm::dot(glm::cross(u, v), origin + (u + v) * Real(0.5) - center) < 0) std::swap(u, v);
            faces[std::size_t(axis * 2 + side)] = make_quad(origin, u, v);
        }
    }
    return faces;
}

}  // namespace rt
