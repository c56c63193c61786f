// The exact answer that ray offsets are judged against: is the segment from a surface point to a light free,
// computed in double precision against the scene's own shapes, and ignoring the shape the point lies on?
// Every shape here is convex or flat (sphere, quad, triangle, box, plane), so a point on it never sees a
// light in front of it (cos θ > 0) through itself: leaving it out is exact, where no offset of a float origin
// is. Shapes are numbered as World numbers its primitives (bounded shapes in scene order, a box as 6, planes
// last), so a Hit's primitive names the shape to leave out.
#pragma once

#include <cstdint>
#include <vector>

#include "rt/core/math.hpp"
#include "rt/core/scene.hpp"

namespace rt {

class ExactVisibility {
  public:
    // Throws InputError for a mesh (a mesh is not convex: leaving all of it out would be wrong).
    explicit ExactVisibility(const Scene& scene);

    // Whether the open segment (p, target) meets no shape other than the one holding World primitive `own`.
    bool visible(std::uint32_t own, const Vec3d& p, const Vec3d& target) const;

  private:
    enum class Kind { kSphere, kQuad, kTriangle, kPlane };
    // A sphere (a = centre, r = radius), a parallelogram (a + x u + y v, x, y in [0, 1]), a triangle (a, a +
    // u, a + v), or a plane (a point a, normal u).
    struct Part {
        Kind kind;
        Vec3d a, u, v;
        double r = 0;
    };
    struct Solid {
        std::uint32_t first_primitive;  // World primitives [first, first + count) are this shape
        std::uint32_t count;
        std::vector<Part> parts;
    };
    static bool blocks(const Part& part, const Vec3d& o, const Vec3d& d);

    std::vector<Solid> solids_;
};

}  // namespace rt
