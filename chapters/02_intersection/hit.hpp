// The hit record: what a ray learns about the nearest surface it meets.
#pragma once

#include <cstdint>

#include "rt/core/math.hpp"

namespace rt {

struct Hit {
    Real t = kInfinity;    // distance along the ray (directions are unit length)
    Vec3 point{0};         // on the surface, computed by the shape from its own parameters (not ray.at(t))
    Vec3 point_error{0};   // per component, |point − exact surface point| <= point_error (rounding bound)
    Vec3 normal{0, 0, 1};  // unit geometric normal, facing the side the ray came from: dot(normal, d) <= 0
    bool front_face =
        true;  // the ray hit the side the shape's outward normal points to (quad: side of u × v)
    // The normal the BSDF is evaluated about: a smooth mesh's vertex normals interpolated with the hit's
    // barycentrics, turned to the viewer's side (shading_normal.hpp); the geometric normal everywhere else.
    Vec3 shading_normal{0, 0, 1};
    // Texture coordinates (chapter 04's textures): a quad's (a, b) of origin + a u + b v (a box's faces are
    // quads: each face's own), a triangle's barycentrics (b1, b2), a mesh's (OBJ vt, PLY u v) interpolated or
    // (b1, b2) without them, a plane's coordinates in its tangent basis (plane_uv, in scene units; in double
    // for a ray from far away, plane_texture_uv), and a sphere's (φ / 2π, 1 − θ / π) about its y axis
    // (sphere_uv). A sphere's costs an atan2 and an acos, so it is computed only when the sphere's material
    // has a texture: (0, 0) otherwise. Double, so that a plane's far from the origin keep their fractions.
    Vec2d uv{0};
    int material = -1;            // index into Scene::materials
    std::uint32_t primitive = 0;  // the primitive's index in the World
    // The light this surface is: k for the k-th primitive, in scene order, whose material emits (a box
    // counts its 6 faces, a mesh its triangles); −1 for a surface that emits nothing and for an emissive
    // plane, which has infinite area and is no light a sampler can draw from. Chapter 04's LightSet numbers
    // its lights the same way, so a path that hits a light knows which one without searching.
    std::int32_t light = -1;
};

// What a ray tracing kernel reports of the nearest hit (Embree's rtcIntersect1 alike): how far, which
// primitive, and where on it — no point, error bound, normal or material (World::nearest). A Hit is built
// from the same search, and more: World::intersect.
struct NearestHit {
    Real t = kInfinity;
    std::uint32_t primitive = 0;  // Hit::primitive's number
    // Where on the primitive: a triangle's barycentrics (b1, b2) of p1 and p2, a quad's (a, b) along u and
    // v; (0, 0) on a sphere or a plane.
    Vec2 uv{0};
};

// Turns the outward normal n toward the ray's side: front_face = d · n < 0, normal = front_face ? n : −n; the
// shading normal is the same until a smooth mesh replaces it.
inline void set_face_normal(Hit& hit, const Vec3& direction, const Vec3& outward_normal) {
    hit.front_face = glm::dot(direction, outward_normal) < 0;
    hit.normal = hit.front_face ? outward_normal : -outward_normal;
    hit.shading_normal = hit.normal;
}

}  // namespace rt
