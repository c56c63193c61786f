#include "bvh_agreement.hpp"

#include <cmath>
#include <sstream>

#include "float_error.hpp"

#include "bvh.hpp"
#include "wide_bvh.hpp"
#include "world.hpp"

namespace rt {

Scene triangle_soup(std::span<const Vec3> corners) {
    MeshShape mesh;
    mesh.positions.assign(corners.begin(), corners.end());
    for (std::uint32_t i = 0; i + 2 < std::uint32_t(corners.size()); i += 3) mesh.triangles.push_back({i, i + 1, i + 2});
    Scene scene;
    scene.materials.push_back(Material{});
    scene.shapes.push_back({std::move(mesh), 0, "soup"});
    return scene;
}

namespace {

// How far a hit's computed distance may be from the exact distance of the surface it reports, from the bound
// its intersection test gives on the hit point (the rays here are of unit length), and t's own rounding.
double rounding_of(const Hit& h) {
    return glm::length(Vec3d(h.point_error)) + double(gamma_bound(3)) * double(h.t);
}

// The same nearest distance. Where surfaces overlap (coplanar triangles), their computed distances differ by
// rounding, and which is "nearest" is rounding noise: distances within both hits' bounds are the same.
bool same_distance(const Hit& a, const Hit& b) {
    return a.t == b.t || std::abs(double(a.t) - double(b.t)) <= rounding_of(a) + rounding_of(b);
}

// The exact distance at which the ray enters the box within [0, t_max], in double, or nothing.
std::optional<double> exact_entry(const Aabb& box, const Ray& ray, double t_max) {
    double t_enter = 0, t_exit = t_max;
    for (int i = 0; i < 3; ++i) {
        const double o = ray.origin[i], d = ray.direction[i];
        if (d == 0) {
            if (o < box.min[i] || o > box.max[i]) return std::nullopt;
            continue;
        }
        double t0 = (double(box.min[i]) - o) / d, t1 = (double(box.max[i]) - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        t_enter = std::max(t_enter, t0);
        t_exit = std::min(t_exit, t1);
    }
    if (t_enter > t_exit) return std::nullopt;
    return t_enter;
}

std::string describe(const BvhQuery& q) {
    std::ostringstream out;
    out.precision(9);
    out << "ray from (" << q.ray.origin.x << ", " << q.ray.origin.y << ", " << q.ray.origin.z << ") along ("
        << q.ray.direction.x << ", " << q.ray.direction.y << ", " << q.ray.direction.z << "), t_max " << q.t_max;
    return out.str();
}

}  // namespace

std::optional<std::string> first_box_disagreement(std::span<const Aabb> boxes, std::span<const BvhQuery> queries) {
    std::vector<std::uint32_t> order;
    const Bvh bvh(boxes, order);
    const WideBvh wide(bvh);
    for (const BvhQuery& q : queries) {
        // A box is hit at its entry rounded to Real, when that is below t_max (and above 0: t = 0, a ray
        // starting inside, counts too).
        auto hit_at = [&](std::uint32_t box, Real limit) -> std::optional<Real> {
            const auto t = exact_entry(boxes[box], q.ray, double(q.t_max));
            if (!t || !(Real(*t) < limit)) return std::nullopt;
            return Real(*t);
        };
        auto test_slot = [&](std::uint32_t slot, Real& limit) {
            const auto t = hit_at(order[slot], limit);
            if (t) limit = *t;
            return t.has_value();
        };
        Real brute = q.t_max;
        for (std::uint32_t b = 0; b < boxes.size(); ++b) brute = hit_at(b, brute).value_or(brute);
        Real found = q.t_max;
        bvh.traverse(q.ray, inverse_direction(q.ray.direction), found, false, test_slot);
        Real found_wide = q.t_max;
        wide.traverse(make_wide_ray(q.ray), found_wide, false, [&](std::uint32_t first, std::uint32_t count, Real& limit) {
            bool hit = false;
            for (std::uint32_t slot = first; slot < first + count; ++slot) hit = test_slot(slot, limit) || hit;
            return hit;
        });
        if (found == brute && found_wide == brute) continue;
        std::ostringstream out;
        out.precision(9);
        out << describe(q) << ": the BVH's nearest box at t " << found << ", the wide BVH's at t " << found_wide
            << ", every box's at t " << brute;
        return out.str();
    }
    return std::nullopt;
}

namespace {

// The first query `accelerated` answers differently from `brute`, or nothing.
std::optional<std::string> first_disagreement(const World& accelerated, const World& brute, const char* name,
                                              std::span<const BvhQuery> queries) {
    for (const BvhQuery& q : queries) {
        const auto a = accelerated.intersect(q.ray, q.t_max);
        const auto b = brute.intersect(q.ray, q.t_max);
        const bool occluded = accelerated.occluded(q.ray, q.t_max);
        if (a.has_value() == b.has_value() && (!a || same_distance(*a, *b)) && occluded == b.has_value()) continue;
        // A hit found by one side alone is a tie with "no hit" when it lies within its rounding of t_max.
        const auto* only = a && !b ? &*a : (b && !a ? &*b : nullptr);
        if (only && !(only->t + rounding_of(*only) < q.t_max) && occluded == a.has_value()) continue;
        std::ostringstream out;
        out.precision(9);
        auto answer = [&](const std::optional<Hit>& h) {
            if (h) out << "hit at t " << h->t; else out << "missed";
        };
        out << describe(q) << ": the " << name << " ";
        answer(a);
        out << ", every primitive ";
        answer(b);
        out << ", the " << name << "'s occlusion " << (occluded ? "yes" : "no");
        return out.str();
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::string> first_bvh_disagreement(const Scene& scene, std::span<const BvhQuery> queries) {
    const World brute(scene, {TriangleTest::kWatertight, Acceleration::kNone});
    const World wide(scene, {TriangleTest::kWatertight, Acceleration::kBvh});
    if (auto disagreement = first_disagreement(wide, brute, "wide BVH", queries)) return disagreement;
    const World binary(scene, {TriangleTest::kWatertight, Acceleration::kBinaryBvh});
    return first_disagreement(binary, brute, "binary BVH", queries);
}

}  // namespace rt
