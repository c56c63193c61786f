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

QuadLight facing(const QuadLight& q, const Vec3& p) {
    if (!q.two_sided || glm::dot(q.normal, p - q.origin) >= 0) return q;
    return QuadLight{q.origin, q.v, q.u, -q.normal, q.area, q.radiance, true};
}

TriangleLight facing(const TriangleLight& t, const Vec3& p) {
    if (!t.two_sided || glm::dot(t.normal, p - t.p0) >= 0) return t;
    return TriangleLight{t.p0, t.p2, t.p1, -t.normal, t.area, t.radiance, true};
}

}  // namespace rt
