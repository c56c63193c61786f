#include "area_lights.hpp"

namespace rt {

QuadLight make_quad_light(const Vec3& origin, const Vec3& u, const Vec3& v, const Color& radiance) {
    const Vec3 n = glm::cross(u, v);
    const Real area = glm::length(n);
    return QuadLight{origin, u, v, area > 0 ? n / area : Vec3{0, 0, 1}, area, radiance};
}

TriangleLight make_triangle_light(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Color& radiance) {
    const Vec3 n = glm::cross(p1 - p0, p2 - p0);
    const Real length = glm::length(n);
    return TriangleLight{p0, p1, p2, length > 0 ? n / length : Vec3{0, 0, 1}, length / 2, radiance};
}

}  // namespace rt
