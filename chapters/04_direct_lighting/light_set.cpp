#include "light_set.hpp"

#include <type_traits>
#include <variant>

namespace rt {
namespace {

// The 6 faces of a transformed box, each as (origin, u, v) turned so u × v points out of the box.
void add_box_faces(const BoxShape& box, const Color& radiance, LightSet& lights) {
    auto corner = [&](int x, int y, int z) {
        return box.transform.apply_to_point(
            {x ? box.max.x : box.min.x, y ? box.max.y : box.min.y, z ? box.max.z : box.min.z});
    };
    const Vec3 center = box.transform.apply_to_point((box.min + box.max) * Real(0.5));
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            int o[3] = {0, 0, 0}, a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
            o[axis] = a[axis] = b[axis] = side;
            a[(axis + 1) % 3] = 1;
            b[(axis + 2) % 3] = 1;
            const Vec3 origin = corner(o[0], o[1], o[2]);
            Vec3 u = corner(a[0], a[1], a[2]) - origin;
            Vec3 v = corner(b[0], b[1], b[2]) - origin;
            if (glm::dot(glm::cross(u, v), origin + (u + v) * Real(0.5) - center) < 0) std::swap(u, v);
            const QuadLight q = make_quad_light(origin, u, v, radiance);
            if (q.area > 0) lights.quads.push_back(q);
        }
    }
}

}  // namespace

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

LightSet collect_lights(const Scene& scene) {
    LightSet lights;
    lights.points = scene.point_lights;
    lights.environment = scene.environment;
    for (const Shape& shape : scene.shapes) {
        const Material& m = scene.material_of(shape);
        if (!m.emissive()) continue;
        const Color L = m.emission;
        std::visit(
            [&](const auto& g) {
                using T = std::decay_t<decltype(g)>;
                if constexpr (std::is_same_v<T, SphereShape>) {
                    if (g.radius > 0) lights.spheres.push_back({g.center, g.radius, L});
                } else if constexpr (std::is_same_v<T, QuadShape>) {
                    const QuadLight q = make_quad_light(g.origin, g.u, g.v, L);
                    if (q.area > 0) lights.quads.push_back(q);
                } else if constexpr (std::is_same_v<T, TriangleShape>) {
                    const TriangleLight t =
                        make_triangle_light(g.vertices[0], g.vertices[1], g.vertices[2], L);
                    if (t.area > 0) lights.triangles.push_back(t);
                } else if constexpr (std::is_same_v<T, BoxShape>) {
                    add_box_faces(g, L, lights);
                } else if constexpr (std::is_same_v<T, MeshShape>) {
                    for (const auto& tri : g.triangles) {
                        const TriangleLight t = make_triangle_light(g.positions[tri[0]], g.positions[tri[1]],
                                                                    g.positions[tri[2]], L);
                        if (t.area > 0) lights.triangles.push_back(t);
                    }
                } else if constexpr (std::is_same_v<T, PlaneShape>) {
                    lights.unsampled.push_back(shape.place + " (an emissive plane has infinite area)");
                }
            },
            shape.geometry);
    }
    return lights;
}

}  // namespace rt
