#include "light_set.hpp"

#include <type_traits>
#include <variant>

#include "02_intersection/box.hpp"

namespace rt {
namespace {

// Adds `light` to `list` when it has an area, and numbers it (Hit::light) either way.
template <class Light>
void add_light(const Light& light, LightRef::List which, std::vector<Light>& list, LightSet& lights) {
    if (area_of(light) > 0) {
        lights.by_hit.push_back({which, std::uint32_t(list.size())});
        list.push_back(light);
    } else {
        lights.by_hit.push_back({});
    }
}

// The 6 faces of a transformed box (chapter 02's box_faces) as one-sided quad lights, emitting outward.
void add_box_faces(const BoxShape& box, const Color& radiance, LightSet& lights) {
    for (const Quad& face : box_faces(box)) {
        add_light(make_quad_light(face.origin, face.u, face.v, radiance), LightRef::List::kQuads,
                  lights.quads, lights);
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
                    add_light(SphereLight{g.center, g.radius, L}, LightRef::List::kSpheres, lights.spheres,
                              lights);
                } else if constexpr (std::is_same_v<T, QuadShape>) {
                    add_light(make_quad_light(g.origin, g.u, g.v, L), LightRef::List::kQuads, lights.quads,
                              lights);
                } else if constexpr (std::is_same_v<T, TriangleShape>) {
                    add_light(make_triangle_light(g.vertices[0], g.vertices[1], g.vertices[2], L),
                              LightRef::List::kTriangles, lights.triangles, lights);
                } else if constexpr (std::is_same_v<T, BoxShape>) {
                    add_box_faces(g, L, lights);
                } else if constexpr (std::is_same_v<T, MeshShape>) {
                    for (const auto& tri : g.triangles) {
                        add_light(make_triangle_light(g.positions[tri[0]], g.positions[tri[1]],
                                                      g.positions[tri[2]], L),
                                  LightRef::List::kTriangles, lights.triangles, lights);
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
