#include "exact_visibility.hpp"

#include <array>
#include <cmath>
#include <type_traits>
#include <variant>

#include "rt/core/errors.hpp"

namespace rt {
namespace {

// A box's 6 faces as parallelograms of its transformed corners (the same float corners World uses).
std::vector<Vec3d> box_corners(const BoxShape& box) {
    std::vector<Vec3d> corners;
    for (int i = 0; i < 8; ++i) {
        corners.emplace_back(box.transform.apply_to_point(
            {i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z}));
    }
    return corners;
}

}  // namespace

ExactVisibility::ExactVisibility(const Scene& scene) {
    std::uint32_t bounded = 0;
    std::vector<Solid> planes;
    for (const Shape& shape : scene.shapes) {
        std::visit(
            [&](const auto& g) {
                using T = std::decay_t<decltype(g)>;
                Solid s{bounded, 1, {}};
                if constexpr (std::is_same_v<T, SphereShape>) {
                    s.parts.push_back({Kind::kSphere, Vec3d(g.center), {}, {}, double(g.radius)});
                } else if constexpr (std::is_same_v<T, QuadShape>) {
                    s.parts.push_back({Kind::kQuad, Vec3d(g.origin), Vec3d(g.u), Vec3d(g.v)});
                } else if constexpr (std::is_same_v<T, TriangleShape>) {
                    const Vec3d p0(g.vertices[0]);
                    s.parts.push_back(
                        {Kind::kTriangle, p0, Vec3d(g.vertices[1]) - p0, Vec3d(g.vertices[2]) - p0});
                } else if constexpr (std::is_same_v<T, PlaneShape>) {
                    s.parts.push_back({Kind::kPlane, Vec3d(g.point), glm::normalize(Vec3d(g.normal)), {}});
                    planes.push_back(s);
                    return;
                } else if constexpr (std::is_same_v<T, BoxShape>) {
                    const std::vector<Vec3d> c = box_corners(g);
                    s.count = 6;
                    // Corner i has x from bit 0, y from bit 1, z from bit 2; each face fixes one bit.
                    for (int axis = 0; axis < 3; ++axis) {
                        for (int side = 0; side < 2; ++side) {
                            const int fixed = side << axis;
                            const int a = 1 << ((axis + 1) % 3), b = 1 << ((axis + 2) % 3);
                            s.parts.push_back({Kind::kQuad, c[std::size_t(fixed)],
                                               c[std::size_t(fixed | a)] - c[std::size_t(fixed)],
                                               c[std::size_t(fixed | b)] - c[std::size_t(fixed)]});
                        }
                    }
                } else if constexpr (std::is_same_v<T, MeshShape>) {
                    throw InputError(
                        scene.file + ": " + shape.place +
                        ": a mesh; the exact visibility of --offset-study takes convex shapes only");
                }
                bounded += s.count;
                solids_.push_back(std::move(s));
            },
            shape.geometry);
    }
    // World numbers its planes after every bounded primitive.
    for (Solid& plane : planes) {
        plane.first_primitive = bounded++;
        solids_.push_back(std::move(plane));
    }
}

bool ExactVisibility::blocks(const Part& part, const Vec3d& o, const Vec3d& d) {
    // The segment o + t d, t in (0, 1).
    auto inside = [](double t) { return t > 0 && t < 1; };
    switch (part.kind) {
        case Kind::kSphere: {
            // |o + t d − c|² = r²: a t² + 2 b t + c₀ = 0, solved with q = −(b + sign(b) √Δ), roots q / a and
            // c₀ / q.
            const Vec3d f = o - part.a;
            const double a = glm::dot(d, d), b = glm::dot(f, d), c0 = glm::dot(f, f) - part.r * part.r;
            const double discriminant = b * b - a * c0;
            if (discriminant < 0) return false;
            const double q = -(b + std::copysign(std::sqrt(discriminant), b));
            return inside(q / a) || (q != 0 && inside(c0 / q));
        }
        case Kind::kPlane: {
            const double denominator = glm::dot(part.u, d);
            return denominator != 0 && inside(glm::dot(part.u, part.a - o) / denominator);
        }
        case Kind::kQuad:
        case Kind::kTriangle: {
            // o + t d = a + x u + y v, solved by Cramer's rule.
            const Vec3d p = glm::cross(d, part.v);
            const double det = glm::dot(part.u, p);
            if (det == 0) return false;
            const Vec3d s = o - part.a;
            const double x = glm::dot(s, p) / det;
            const Vec3d q = glm::cross(s, part.u);
            const double y = glm::dot(d, q) / det;
            const double t = glm::dot(part.v, q) / det;
            if (!inside(t) || x < 0 || y < 0) return false;
            return part.kind == Kind::kQuad ? x <= 1 && y <= 1 : x + y <= 1;
        }
    }
    return false;
}

bool ExactVisibility::visible(std::uint32_t own, const Vec3d& p, const Vec3d& target) const {
    const Vec3d d = target - p;
    for (const Solid& solid : solids_) {
        if (own >= solid.first_primitive && own < solid.first_primitive + solid.count) continue;
        for (const Part& part : solid.parts) {
            if (blocks(part, p, d)) return false;
        }
    }
    return true;
}

}  // namespace rt
