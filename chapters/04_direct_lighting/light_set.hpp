// The lights of a scene, in the forms chapter 04 samples: every shape whose material has an emission is an
// area light (quads, box faces, triangles and mesh triangles sampled by area; spheres by solid angle), plus
// point lights and the uniform environment. Area lights are one-sided: they emit on their front side
// (a quad: the side of u × v; a triangle: counter-clockwise; a sphere: outward).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rt/core/scene.hpp"

namespace rt {

// The parallelogram origin + a u + b v (a, b in [0, 1]) emitting radiance L on the side of normal = unit(u ×
// v).
struct QuadLight {
    Vec3 origin{0};
    Vec3 u{1, 0, 0};
    Vec3 v{0, 1, 0};
    Vec3 normal{0, 0, 1};
    Real area = 1;  // |u × v|
    Color radiance{1};
};

// The triangle p0 p1 p2 emitting on the side of normal = unit((p1 − p0) × (p2 − p0)).
struct TriangleLight {
    Vec3 p0{0};
    Vec3 p1{1, 0, 0};
    Vec3 p2{0, 1, 0};
    Vec3 normal{0, 0, 1};
    Real area = Real(0.5);
    Color radiance{1};
};

struct SphereLight {
    Vec3 center{0};
    Real radius = 1;
    Color radiance{1};
};

// The emitting area of a light: |u × v| for a quad, half that for a triangle, 4π r² for a sphere.
inline Real area_of(const QuadLight& q) {
    return q.area;
}
inline Real area_of(const TriangleLight& t) {
    return t.area;
}
inline Real area_of(const SphereLight& s) {
    return 4 * kPi * s.radius * s.radius;
}

// Where light number k of Hit::light is in a LightSet: its list and its place there (kNone for a degenerate
// emitter of zero area, which is left out).
struct LightRef {
    enum class List : std::uint8_t { kQuads, kTriangles, kSpheres, kNone };
    List list = List::kNone;
    std::uint32_t index = 0;
};

struct LightSet {
    std::vector<QuadLight> quads;
    std::vector<TriangleLight> triangles;
    std::vector<SphereLight> spheres;
    std::vector<PointLight> points;
    std::optional<EnvironmentLight> environment;
    // Emitters that cannot be sampled (an infinite plane): they are seen by camera rays only.
    std::vector<std::string> unsampled;
    // By Hit::light: every emissive bounded primitive in scene order, numbered as chapter 02's World numbers
    // them.
    std::vector<LightRef> by_hit;

    std::size_t area_count() const { return quads.size() + triangles.size() + spheres.size(); }
    bool empty() const { return area_count() == 0 && points.empty() && !environment; }
};

QuadLight make_quad_light(const Vec3& origin, const Vec3& u, const Vec3& v, const Color& radiance);
TriangleLight make_triangle_light(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Color& radiance);

// Every light of the scene. Degenerate emitters (zero area) are left out: they emit no power.
LightSet collect_lights(const Scene& scene);

}  // namespace rt
