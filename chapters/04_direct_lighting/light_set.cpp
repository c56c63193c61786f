#include "light_set.hpp"

#include <type_traits>
#include <variant>

#include "02_intersection/aabb.hpp"
#include "02_intersection/box.hpp"
#include "03_shadow_rays/scene_scale.hpp"
#include "distant_emitter.hpp"
#include "point_emitter.hpp"
#include "quad_emitter.hpp"
#include "sphere_emitter.hpp"
#include "spot_emitter.hpp"
#include "triangle_emitter.hpp"

namespace rt {
namespace {

// The area lights, gathered by kind in scene order, and for each emissive primitive (Hit::light) its kind
// and its place there, or none.
class AreaLights {
  public:
    enum Kind { kQuads, kTriangles, kSpheres, kKinds };

    // Adds `light` to its kind's list when it has an area, and numbers it (Hit::light) either way.
    template <class Emitter, class Geometry>
    void add(const Geometry& shape, Kind kind) {
        if (area_of(shape) > 0) {
            by_hit_.push_back({kind, int(lists_[kind].size())});
            lists_[kind].push_back(std::make_shared<Emitter>(shape));
        } else {
            by_hit_.push_back({kKinds, -1});
        }
    }

    // The lists one after the other, and Hit::light numbered into that order.
    void append_to(LightSet& lights) const {
        int first[kKinds + 1] = {};
        for (int kind = 0; kind < kKinds; ++kind) {
            first[kind] = int(lights.lights.size());
            lights.lights.insert(lights.lights.end(), lists_[kind].begin(), lists_[kind].end());
        }
        for (const Place& place : by_hit_)
            lights.by_hit.push_back(place.index < 0 ? -1 : first[place.kind] + place.index);
    }

  private:
    struct Place {
        Kind kind;
        int index;
    };
    std::vector<std::shared_ptr<const Light>> lists_[kKinds];
    std::vector<Place> by_hit_;
};

// The 6 faces of a transformed box (chapter 02's box_faces) as one-sided quad lights, emitting outward.
// `light` emitting on both sides when `two_sided` (the material's).
template <class Planar>
Planar sided(Planar light, bool two_sided) {
    light.two_sided = two_sided;
    return light;
}

void add_box_faces(const BoxShape& box, const Color& radiance, bool two_sided, AreaLights& lights) {
    for (const Quad& face : box_faces(box)) {
        lights.add<QuadEmitter>(sided(make_quad_light(face.origin, face.u, face.v, radiance), two_sided),
                                AreaLights::kQuads);
    }
}

// Each of `descriptions` (the scene's lights of one kind) as an Emitter made from it and `more`.
template <class Emitter, class Description, class... More>
void add_each(const std::vector<Description>& descriptions, LightSet& lights, const More&... more) {
    for (const Description& d : descriptions) lights.lights.push_back(std::make_shared<Emitter>(d, more...));
}

// The sphere around the box of every shape's extent (chapter 03's for_each_shape_extent). A scene of planes
// alone gives one point (no shape: none), and the camera's eye is added, so that a distant light there keeps
// a power to be picked by.
BoundingSphere bounding_sphere(const Scene& scene) {
    Aabb box;
    for_each_shape_extent(scene, [&](const Vec3& p) { box.extend(p); });
    if (!glm::any(glm::lessThan(box.min, box.max))) box.extend(scene.camera.from);
    return {box.center(), glm::length(box.max - box.center())};
}

}  // namespace

LightSet collect_lights(const Scene& scene) {
    LightSet lights;
    lights.environment = scene.environment;
    AreaLights area;
    for (const Shape& shape : scene.shapes) {
        const Material& m = scene.material_of(shape);
        if (!m.emissive()) continue;
        const Color L = m.emission;
        std::visit(
            [&](const auto& g) {
                using T = std::decay_t<decltype(g)>;
                if constexpr (std::is_same_v<T, SphereShape>) {
                    area.add<SphereEmitter>(SphereLight{g.center, g.radius, L}, AreaLights::kSpheres);
                } else if constexpr (std::is_same_v<T, QuadShape>) {
                    area.add<QuadEmitter>(sided(make_quad_light(g.origin, g.u, g.v, L), m.two_sided),
                                          AreaLights::kQuads);
                } else if constexpr (std::is_same_v<T, TriangleShape>) {
                    area.add<TriangleEmitter>(
                        sided(make_triangle_light(g.vertices[0], g.vertices[1], g.vertices[2], L),
                              m.two_sided),
                        AreaLights::kTriangles);
                } else if constexpr (std::is_same_v<T, BoxShape>) {
                    add_box_faces(g, L, m.two_sided, area);
                } else if constexpr (std::is_same_v<T, MeshShape>) {
                    for (const auto& tri : g.triangles) {
                        const TriangleLight t = make_triangle_light(g.positions[tri[0]], g.positions[tri[1]],
                                                                    g.positions[tri[2]], L);
                        area.add<TriangleEmitter>(sided(t, m.two_sided), AreaLights::kTriangles);
                    }
                } else if constexpr (std::is_same_v<T, PlaneShape>) {
                    lights.unsampled.push_back(shape.place + " (an emissive plane has infinite area)");
                }
            },
            shape.geometry);
    }
    area.append_to(lights);
    add_each<PointEmitter>(scene.point_lights, lights);
    if (!scene.distant_lights.empty())
        add_each<DistantEmitter>(scene.distant_lights, lights, bounding_sphere(scene));
    add_each<SpotEmitter>(scene.spot_lights, lights);
    return lights;
}

}  // namespace rt
