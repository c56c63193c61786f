// Chapter 02: intersection. Plain cases first, then the hard cases ([stability]): each robust form against a
// double-precision reference computed from the same float inputs, and the naive form shown failing.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <span>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/aabb.hpp"
#include "02_intersection/bvh_agreement.hpp"
#include "02_intersection/intersection_render.hpp"
#include "02_intersection/leak_probe.hpp"
#include "02_intersection/mesh_generator.hpp"
#include "02_intersection/quad_packet.hpp"
#include "02_intersection/triangle_packet.hpp"
#include "02_intersection/wide_bvh.hpp"
#include "02_intersection/world.hpp"
#include "random_unit.hpp"
#include "rt/core/random.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/scene_loader.hpp"

using namespace rt;

namespace {

Scene scene_of(std::vector<Shape> shapes) {
    Scene scene;
    scene.materials.push_back(Material{});
    scene.shapes = std::move(shapes);
    return scene;
}

bool finite_hit(const Hit& h) {
    return std::isfinite(h.t) && is_finite(h.point) && is_finite(h.normal);
}

// The sphere's nearest positive root in double from the float ray and sphere (stable form), or −1 on a miss.
double reference_sphere_t(const Ray& ray, const Sphere& sphere) {
    const Vec3d f = Vec3d(ray.origin) - Vec3d(sphere.center);
    const Vec3d d{ray.direction};
    const double a = glm::dot(d, d);
    const double b = glm::dot(f, d) / a;
    const Vec3d perpendicular = f - b * d;
    const double r = double(sphere.radius);
    const double discriminant = r * r - glm::dot(perpendicular, perpendicular);
    if (discriminant < 0) return -1;
    const double c = (glm::dot(f, f) - r * r) / a;
    const double q = -(b + std::copysign(std::sqrt(discriminant / a), b));
    const double t0 = std::min(q, c / q), t1 = std::max(q, c / q);
    return t0 > 0 ? t0 : (t1 > 0 ? t1 : -1);
}

Real ulp(Real x) {
    return std::nextafter(std::abs(x), kInfinity) - std::abs(x);
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Plain cases

TEST_CASE("A ray hits the near side of a sphere in front of it", "[sphere][ex:ch02.sphere_stable]") {
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    const auto t = intersect_sphere(ray, Sphere{{0, 0, -5}, 1}, kInfinity);
    REQUIRE(t);
    CHECK(*t == Approx(4));
    CHECK_FALSE(intersect_sphere(ray, Sphere{{0, 3, -5}, 1}, kInfinity));
    CHECK_FALSE(intersect_sphere(ray, Sphere{{0, 0, -5}, 1}, 3));
    CHECK_FALSE(intersect_sphere(Ray{{0, 0, 0}, {0, 0, 1}}, Sphere{{0, 0, -5}, 1}, kInfinity));
}

TEST_CASE("Quads are hit inside their parallelogram with coordinates a and b", "[quad][ex:ch02.quad]") {
    const Quad quad = make_quad({0, 0, -2}, {2, 0, 0}, {1, 1, 0});
    const auto hit = intersect_quad(Ray{{1.5f, 0.5f, 0}, {0, 0, -1}}, quad, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(2));
    CHECK(hit->ab.x == Approx(0.5));
    CHECK(hit->ab.y == Approx(0.5));
    CHECK_FALSE(
        intersect_quad(Ray{{0.2f, 0.5f, 0}, {0, 0, -1}}, quad, kInfinity));      // left of the slanted side
    CHECK_FALSE(intersect_quad(Ray{{1, 0.5f, 0}, {1, 0, 0}}, quad, kInfinity));  // parallel
    CHECK_FALSE(intersect_quad(Ray{{1, 0.5f, 0}, {0, 0, -1}}, make_quad({0, 0, -2}, {1, 0, 0}, {2, 0, 0}),
                               kInfinity));  // degenerate
}

TEST_CASE("A quad hit's coordinates rebuild the hit point on slanted, stretched quads",
          "[quad][ex:ch02.quad]") {
    // Whatever the derivation, (a, b) are the point's coordinates: Q + a u + b v is the hit point. Edges neither
    // unit nor at right angles, so a projection on u or v alone, or a missing 1 / (n · n), is off.
    const Quad quad = make_quad({1, -2, 3}, {3, 1, -0.5f}, {1.5f, 2.5f, 1});
    Pcg32 rng(21, 4);
    int wrong = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec2 ab = rng.next_vec2();
        const Vec3 target = quad.origin + ab.x * quad.u + ab.y * quad.v;
        const Vec3 origin = target + (random_unit(rng) + quad.normal * Real(1.5)) * Real(4);
        const auto hit = intersect_quad(Ray{origin, glm::normalize(target - origin)}, quad, kInfinity);
        if (!hit || std::abs(hit->ab.x - ab.x) > 1e-4f || std::abs(hit->ab.y - ab.y) > 1e-4f) ++wrong;
    }
    INFO("hits whose (a, b) are not the point's coordinates: Q + a u + b v is not the hit point");
    CHECK(wrong == 0);
}

TEST_CASE("Planes are hit from either side and never by a parallel ray", "[plane][ex:ch02.plane]") {
    const Plane plane = make_plane({0, -1, 0}, {0, 2, 0});
    CHECK(plane.normal == Vec3{0, 1, 0});
    const auto t = intersect_plane(Ray{{0, 1, 0}, {0, -1, 0}}, plane, kInfinity);
    REQUIRE(t);
    CHECK(*t == Approx(2));
    CHECK(intersect_plane(Ray{{0, -3, 0}, {0, 1, 0}}, plane, kInfinity));
    CHECK_FALSE(intersect_plane(Ray{{0, 1, 0}, {1, 0, 0}}, plane, kInfinity));
    CHECK_FALSE(intersect_plane(Ray{{0, 1, 0}, {0, 1, 0}}, plane, kInfinity));
}

TEST_CASE("Both roots of a sphere in front of, around and behind the origin, in order, from both forms",
          "[sphere][ex:ch02.sphere_stable][ex:ch02.sphere_textbook]") {
    // A unit sphere 5 along the ray: roots 4 and 6; around the origin: −1 and 1; 5 behind: −6 and −4.
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    const struct {
        Real z, t0, t1;
    } cases[] = {{-5, 4, 6}, {0, -1, 1}, {5, -6, -4}};
    for (const auto& c : cases) {
        const Sphere sphere{{0, 0, c.z}, 1};
        for (const auto& roots : {sphere_roots_stable(ray, sphere), sphere_roots_textbook(ray, sphere)}) {
            INFO("sphere at z = " << c.z);
            REQUIRE(roots);
            CHECK(roots->t0 == Approx(c.t0));
            CHECK(roots->t1 == Approx(c.t1));
        }
    }
    CHECK_FALSE(sphere_roots_textbook(ray, Sphere{{0, 3, -5}, 1}));
    CHECK_FALSE(intersect_sphere(ray, Sphere{{0, 0, 5}, 1}, kInfinity));  // behind: no hit
}

TEST_CASE("A triangle behind the ray's origin is not hit, by either test",
          "[triangle][ex:ch02.triangle_moller][ex:ch02.triangle_watertight]") {
    const Triangle tri{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    for (TriangleTest test : {TriangleTest::kWatertight, TriangleTest::kMollerTrumbore}) {
        CHECK_FALSE(intersect_triangle(Ray{{0.25f, 0.25f, 0}, {0, 0, -1}}, tri, kInfinity, test));
        CHECK(intersect_triangle(Ray{{0.25f, 0.25f, 0}, {0, 0, 1}}, tri, kInfinity, test));
    }
}

TEST_CASE("A ray leaving a triangle from its own hit point, away from its plane, never hits it again",
          "[triangle][stability][ex:ch02.triangle_watertight]") {
    // Long slivers far from the origin: the hit point o + t d lies off the plane by rounding, and a ray from it
    // that leaves the plane on the side where it lies can still compute a tiny t > 0 for the same triangle.
    // The watertight test accepts t only beyond its bound δt on the rounding of t.
    Pcg32 rng(29, 8);
    int leaving = 0, rehits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 centre = (Vec3{rng.next_real(), rng.next_real(), rng.next_real()} - Real(0.5)) * Real(2e4);
        const Vec3 along = random_unit(rng) * Real(100), across = random_unit(rng) * Real(0.01);
        const Triangle tri{centre - along, centre + along, centre + across};
        const Vec3 target = centre + Real(0.4) * across + (rng.next_real() - Real(0.5)) * along;
        const Vec3 origin = target + random_unit(rng) * Real(10);
        const Ray ray{origin, glm::normalize(target - origin)};
        const auto hit = intersect_triangle(ray, tri, kInfinity, TriangleTest::kWatertight);
        if (!hit) continue;
        const Vec3 p = ray.at(hit->t);
        // Which side of the plane p lies on, in double (products of floats are exact there).
        const Vec3d n = glm::cross(Vec3d(tri.p1) - Vec3d(tri.p0), Vec3d(tri.p2) - Vec3d(tri.p0));
        const double side = glm::dot(n, Vec3d(p) - Vec3d(tri.p0));
        if (side == 0) continue;
        Vec3 d = random_unit(rng);
        if ((glm::dot(Vec3d(d), n) > 0) != (side > 0)) d = -d;
        if (glm::dot(Vec3d(d), n) == 0) continue;
        ++leaving;
        if (intersect_triangle(Ray{p, d}, tri, kInfinity, TriangleTest::kWatertight)) ++rehits;
    }
    INFO(leaving << " rays leaving");
    CHECK(leaving > 10000);
    CHECK(rehits == 0);
}

TEST_CASE("Rays aimed exactly at a box's corners and at points of its edges enter it, and a box behind is missed",
          "[bvh][ex:ch02.slab_test][ex:ch02.slab_widening]") {
    // The box's own corner and edge points, from random origins far and near: the three slabs' distances are
    // rounded apart, and only widening entry and exit by their rounding bound keeps the entry before the exit.
    Pcg32 rng(17, 3);
    int missed = 0, rays = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 lo = (Vec3{rng.next_real(), rng.next_real(), rng.next_real()} - Real(0.5)) * Real(200);
        const Vec3 size = Vec3{rng.next_real(), rng.next_real(), rng.next_real()} * Real(10) + Real(0.01);
        const Aabb box{lo, lo + size};
        Vec3 target = lo;
        for (int axis = 0; axis < 3; ++axis) {
            const Real pick = rng.next_real();
            target[axis] = pick < Real(0.4) ? box.min[axis] : pick < Real(0.8) ? box.max[axis]
                                                             : box.min[axis] + rng.next_real() * size[axis];
        }
        const Vec3 origin = target + random_unit(rng) * (Real(1) + rng.next_real() * Real(1000));
        const Vec3 d = glm::normalize(target - origin);
        const bool inside = glm::all(glm::greaterThanEqual(origin, box.min)) && glm::all(glm::lessThanEqual(origin, box.max));
        if (!is_finite(d) || inside) continue;
        ++rays;
        if (slab_entry(box, Ray{origin, d}, inverse_direction(d), kInfinity) == kInfinity) ++missed;
        // The same box behind the origin.
        if (slab_entry(box, Ray{origin, -d}, inverse_direction(-d), kInfinity) != kInfinity) ++missed;
    }
    INFO(rays << " rays; a miss of a point on the box's surface: the slab distances' rounding is not covered");
    CHECK(missed == 0);
}

TEST_CASE("The slab test's widening stays within rounding: clear misses miss and the entry is near the exact one",
          "[bvh][ex:ch02.slab_test][ex:ch02.slab_widening]") {
    // Any correct bound is a few γₙ: a ray passing a box a thousandth of its size away misses it, and the entry
    // distance is the exact one (in double) to a relative 10⁻⁵.
    Pcg32 rng(23, 5);
    int too_loose = 0, entry_off = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 lo = (Vec3{rng.next_real(), rng.next_real(), rng.next_real()} - Real(0.5)) * Real(200);
        const Real size = Real(0.5) + rng.next_real() * Real(10);
        const Aabb box{lo, lo + Vec3{size}};
        // A line past the edge x = max, y = max by 10⁻³ of the box, square to the edge's diagonal (1, 1, 0): on
        // it x + y stays above max.x + max.y, so it misses the box.
        const Vec3 past = box.max + Vec3{1, 1, 0} * (size * Real(1e-3));
        const Vec3 along = glm::normalize(Vec3{1, -1, 0} * (rng.next_real() - Real(0.5)) +
                                          Vec3{0, 0, 1} * (rng.next_real() - Real(0.5)));
        const Vec3 start = past - along * Real(20 + rng.next_real() * 100);
        if (is_finite(along) && slab_entry(box, Ray{start, along}, inverse_direction(along), kInfinity) < kInfinity)
            ++too_loose;
        const Vec3 origin = box.center() + random_unit(rng) * Real(20 + rng.next_real() * 100);
        const Vec3 d = glm::normalize(box.center() - origin);
        const Real t = slab_entry(box, Ray{origin, d}, inverse_direction(d), kInfinity);
        double exact = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const double face = d[axis] > 0 ? box.min[axis] : box.max[axis];
            exact = std::max(exact, (face - double(origin[axis])) / double(d[axis]));
        }
        if (!(std::abs(double(t) - exact) <= 1e-5 * exact)) ++entry_off;
    }
    INFO("boxes entered by a ray that clearly misses them, or entries far from the exact distance: a widening "
         "larger than the rounding can be");
    CHECK(too_loose == 0);
    CHECK(entry_off == 0);
}

TEST_CASE("Both triangle tests agree on a plain triangle and give barycentrics",
          "[triangle][ex:ch02.triangle_moller][ex:ch02.triangle_watertight]") {
    const Triangle tri{{0, 0, -1}, {1, 0, -1}, {0, 1, -1}};
    for (TriangleTest test : {TriangleTest::kWatertight, TriangleTest::kMollerTrumbore}) {
        const auto hit = intersect_triangle(Ray{{0.25f, 0.5f, 0}, {0, 0, -1}}, tri, kInfinity, test);
        REQUIRE(hit);
        CHECK(hit->t == Approx(1));
        CHECK(hit->barycentrics.x == Approx(0.25));
        CHECK(hit->barycentrics.y == Approx(0.5));
        CHECK(intersect_triangle(Ray{{0.25f, 0.5f, -2}, {0, 0, 1}}, tri, kInfinity, test));  // the back side
        CHECK_FALSE(intersect_triangle(Ray{{0.75f, 0.5f, 0}, {0, 0, -1}}, tri, kInfinity, test));
        CHECK_FALSE(intersect_triangle(Ray{{0.25f, 0.5f, 0}, {0, 0, -1}}, tri, Real(0.5), test));
    }
}

TEST_CASE("The world returns the nearest of several shapes with a normal facing the ray",
          "[world][ex:ch02.plane][ex:ch02.quad][ex:ch02.quad_packet][ex:ch02.sphere_stable]") {
    std::vector<Shape> shapes;
    shapes.push_back({SphereShape{{0, 0, -10}, 1}, 0, "s"});
    shapes.push_back({QuadShape{{-1, -1, -5}, {2, 0, 0}, {0, 2, 0}}, 0, "q"});
    shapes.push_back({PlaneShape{{0, 0, -20}, {0, 0, 1}}, 0, "p"});
    for (Acceleration accel : {Acceleration::kBvh, Acceleration::kNone}) {
        const World world(scene_of(shapes), {TriangleTest::kWatertight, accel});
        CHECK(world.primitive_count() == 3);
        const auto hit = world.intersect(Ray{{0, 0, 0}, {0, 0, -1}});
        REQUIRE(hit);
        CHECK(hit->t == Approx(5));
        CHECK(hit->primitive == 1);
        CHECK(hit->front_face);
        CHECK(hit->normal == Vec3{0, 0, 1});
        // The same search without the hit record: the distance, the primitive, and where on the quad.
        const auto nearest = world.nearest(Ray{{0, 0, 0}, {0, 0, -1}});
        REQUIRE(nearest);
        CHECK(nearest->t == hit->t);
        CHECK(nearest->primitive == 1);
        CHECK(nearest->uv == Vec2{0.5f, 0.5f});
        CHECK_FALSE(world.nearest(Ray{{0, 0, 0}, {0, 0, -1}}, 4));
        CHECK(world.occluded(Ray{{0, 0, 0}, {0, 0, -1}}, 6));
        CHECK_FALSE(world.occluded(Ray{{0, 0, 0}, {0, 0, -1}}, 4));
        const auto far = world.intersect(Ray{{5, 0, 0}, {0, 0, -1}});
        REQUIRE(far);
        CHECK(far->primitive == 2);
        CHECK(far->t == Approx(20));
        CHECK(world.nearest(Ray{{5, 0, 0}, {0, 0, -1}})->primitive == 2);
        const auto back = world.intersect(Ray{{0, 0, -7}, {0, 0, 1}});  // the quad's back side
        REQUIRE(back);
        CHECK_FALSE(back->front_face);
        CHECK(back->normal == Vec3{0, 0, -1});
    }
}

TEST_CASE("A transformed box becomes six quads with outward normals", "[world][ex:ch02.quad_packet]") {
    BoxShape box{{0, 0, 0}, {1, 2, 1}, {}};
    box.transform.rotate_degrees = {0, 90, 0};
    box.transform.translate = {10, 0, 0};
    const World world(scene_of({Shape{box, 0, "b"}}));
    CHECK(world.primitive_count() == 6);
    // Turned 90° about y, the box spans x in [10, 11], z in [−1, 0].
    const auto hit = world.intersect(Ray{{10.5f, 1, 5}, {0, 0, -1}});
    REQUIRE(hit);
    CHECK(hit->t == Approx(5).margin(1e-5));
    CHECK(hit->front_face);
    CHECK(hit->normal.z == Approx(1));
    const auto inside = world.intersect(Ray{{10.5f, 1, -0.5f}, {0, 1, 0}});
    REQUIRE(inside);
    CHECK(inside->t == Approx(1));
    CHECK_FALSE(inside->front_face);
    CHECK(inside->normal.y == Approx(-1));
}

TEST_CASE("Generated spheres are closed meshes with the announced triangle counts", "[mesh]") {
    const MeshShape ico = make_icosphere(2);
    CHECK(ico.triangles.size() == 320);
    CHECK(ico.positions.size() == 162);
    CHECK(is_closed(ico));
    const MeshShape uv = make_uv_sphere(12, 7);
    CHECK(uv.triangles.size() == 2 * 12 * 6);
    CHECK(is_closed(uv));
    MeshShape open = ico;
    open.triangles.pop_back();
    CHECK_FALSE(is_closed(open));
    // Counter-clockwise seen from outside: every outward normal points away from the centre.
    for (const auto& t : uv.triangles) {
        const Triangle tri{uv.positions[t[0]], uv.positions[t[1]], uv.positions[t[2]]};
        CHECK(glm::dot(triangle_normal(tri), tri.p0 + tri.p1 + tri.p2) > 0);
    }
}

namespace {

// Every primitive in exactly one leaf, every box containing its children's and its primitives' boxes.
void check_hierarchy(const Bvh& bvh, std::span<const Aabb> boxes, const std::vector<std::uint32_t>& order) {
    std::vector<int> seen(boxes.size(), 0);
    for (std::size_t n = 0; n < bvh.nodes().size(); ++n) {
        const BvhNode& node = bvh.nodes()[n];
        auto contains = [&](const Aabb& inner) {
            return glm::all(glm::lessThanEqual(node.min, inner.min)) &&
                   glm::all(glm::lessThanEqual(inner.max, node.max));
        };
        if (node.leaf()) {
            for (std::uint32_t i = node.offset; i < node.offset + node.count; ++i) {
                ++seen[order[i]];
                CHECK(contains(boxes[order[i]]));
            }
        } else {
            CHECK(contains(bvh.nodes()[n + 1].box()));
            CHECK(contains(bvh.nodes()[node.offset].box()));
        }
    }
    for (int s : seen) CHECK(s == 1);
}

}  // namespace

TEST_CASE("The BVH holds every primitive once, in boxes that contain their children", "[bvh]") {
    Pcg32 rng(7, 1);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 500; ++i) {
        Aabb b;
        const Vec3 c{rng.next_real() * 10, rng.next_real() * 10, rng.next_real() * 10};
        b.extend(c);
        b.extend(c + Vec3{rng.next_real(), rng.next_real(), rng.next_real()});
        boxes.push_back(b);
    }
    std::vector<std::uint32_t> order;
    const Bvh bvh(boxes, order);
    check_hierarchy(bvh, boxes, order);
    CHECK(bvh.bytes() <= boxes.size() * 64);  // the lesson's memory target: 64 bytes per primitive at most
}

// Above 2^14 primitives in the root's second child, the build makes that subtree on a second thread and
// appends its nodes after the first child's: each of its interior nodes' second-child index is moved.
TEST_CASE("A BVH whose second subtree is built on another thread holds every primitive once, in boxes that "
          "contain their children",
          "[bvh]") {
    Pcg32 rng(7, 3);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 60000; ++i) {
        Aabb b;
        const Vec3 c{rng.next_real() * 100, rng.next_real() * 100, rng.next_real() * 100};
        b.extend(c);
        b.extend(c + Vec3{rng.next_real(), rng.next_real(), rng.next_real()});
        boxes.push_back(b);
    }
    std::vector<std::uint32_t> order;
    const Bvh bvh(boxes, order);
    REQUIRE(bvh.nodes().size() > 2);
    CHECK(bvh.nodes().size() - bvh.nodes()[0].offset > (1u << 14) / 8);  // the second subtree is large
    check_hierarchy(bvh, boxes, order);
}

TEST_CASE("The wide BVH holds every leaf of the binary one once, in the binary nodes' boxes", "[bvh]") {
    Pcg32 rng(7, 2);
    for (const int count : {1, 3, 5, 40, 3000}) {
        INFO(count << " boxes");
        std::vector<Aabb> boxes;
        for (int i = 0; i < count; ++i) {
            Aabb b;
            const Vec3 c{rng.next_real() * 10, rng.next_real() * 10, rng.next_real() * 10};
            b.extend(c);
            b.extend(c + Vec3{rng.next_real(), rng.next_real(), rng.next_real()});
            boxes.push_back(b);
        }
        std::vector<std::uint32_t> order;
        const Bvh bvh(boxes, order);
        const WideBvh wide(bvh);
        // Every slot in exactly one leaf, whose box contains its primitives; every interior child's box
        // contains its own children's; every node but the root is some node's child exactly once.
        std::vector<int> seen(boxes.size(), 0), parents(wide.nodes().size(), 0);
        std::size_t children = 0;
        for (const WideBvhNode& node : wide.nodes()) {
            for (int k = 0; k < kWideBvhWidth; ++k) {
                const Aabb box = node.box(k);
                if (!(box.min.x <= box.max.x)) {  // unused: the empty box, no child
                    CHECK(node.count[std::size_t(k)] == 0);
                    continue;
                }
                ++children;
                auto contains = [&](const Aabb& inner) {
                    return glm::all(glm::lessThanEqual(box.min, inner.min)) &&
                           glm::all(glm::lessThanEqual(inner.max, box.max));
                };
                const std::uint32_t c = node.child[std::size_t(k)], n = node.count[std::size_t(k)];
                if (n > 0) {
                    for (std::uint32_t slot = c; slot < c + n; ++slot) {
                        ++seen[order[slot]];
                        CHECK(contains(boxes[order[slot]]));
                    }
                } else {
                    REQUIRE(c < wide.nodes().size());
                    ++parents[c];
                    for (int j = 0; j < kWideBvhWidth; ++j) {
                        const Aabb inner = wide.nodes()[c].box(j);
                        if (inner.min.x <= inner.max.x) CHECK(contains(inner));
                    }
                }
            }
        }
        for (int s : seen) CHECK(s == 1);
        CHECK(parents[0] == 0);
        for (std::size_t n = 1; n < parents.size(); ++n) CHECK(parents[n] == 1);
        // Four children a node where the binary tree has them: fewer nodes than half the binary ones, plus one.
        CHECK(wide.nodes().size() <= bvh.nodes().size() / 2 + 1);
        // Every binary leaf is a wide leaf, and every wide node but the root is a child.
        const auto binary_leaves = std::count_if(bvh.nodes().begin(), bvh.nodes().end(),
                                                 [](const BvhNode& node) { return node.leaf(); });
        CHECK(children == std::size_t(binary_leaves) + wide.nodes().size() - 1);
    }
}

TEST_CASE("The default scene renders finite, plausible and identical on 1 and 2 threads",
          "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch02.quad_packet]"
          "[ex:ch02.slab_widening][ex:ch02.sphere_stable][ex:ch02.wide_bvh_traversal]") {
    const Scene scene = load_scene(scene_path("ch02_default.json"));
    const World world(scene);
    RenderSettings settings{64, 36, 1, 1, 1, ProgressStyle::kNone};
    const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
    const RenderResult one = render_intersections(world, camera, ShowMode::kNormal, 5, settings);
    settings.threads = 2;
    const RenderResult two = render_intersections(world, camera, ShowMode::kNormal, 5, settings);
    double sum = 0;
    bool identical = true;
    for (int y = 0; y < settings.height; ++y) {
        for (int x = 0; x < settings.width; ++x) {
            const Color c = one.image.at(x, y);
            REQUIRE(is_finite(c));
            sum += double(c.r + c.g + c.b) / 3;
            identical = identical && c == two.image.at(x, y);
        }
    }
    CHECK(identical);
    const double mean = sum / (settings.width * settings.height);
    CHECK(mean > 0.3);
    CHECK(mean < 0.9);
    CHECK(one.rays[RayKind::kCamera] == 64u * 36u);
    CHECK(one.rays[RayKind::kShadow] == 0);
}

// ---------------------------------------------------------------------------------------------------------
// Hard cases ([stability])

namespace {

// A closed, jittered icosphere (shared vertices), moved off the origin so rounding is not symmetric.
MeshShape jittered_closed_mesh(int subdivisions) {
    MeshShape mesh = make_icosphere(subdivisions);
    jitter_radii(mesh, Real(0.05), 11);
    for (Vec3& p : mesh.positions) p = p * Real(3.7) + Vec3{10.3f, -5.1f, 2.9f};
    return mesh;
}

// How many of `rays` miss the mesh.
std::uint64_t escaped(const World& world, const std::vector<Ray>& rays) {
    std::uint64_t count = 0;
    for (const Ray& ray : rays) count += world.intersect(ray) ? 0 : 1;
    return count;
}

}  // namespace

TEST_CASE("Rays from inside a closed mesh never escape the watertight test",
          "[stability][triangle][ex:ch02.bvh_traversal][ex:ch02.slab_test][ex:ch02.slab_widening]"
          "[ex:ch02.triangle_moller]"
          "[ex:ch02.triangle_watertight][ex:ch02.wide_bvh_traversal]") {
    const MeshShape mesh = jittered_closed_mesh(4);  // 5120 triangles, 2562 vertices, 7680 edges
    REQUIRE(is_closed(mesh));
    const Vec3 centre{10.3f, -5.1f, 2.9f};
    std::vector<Ray> rays;
    // Aimed exactly at every vertex and at 1/8, 2/8, ..., 7/8 of every edge: where triangles meet.
    for (const Vec3& p : mesh.positions) rays.push_back({centre, glm::normalize(p - centre)});
    for (const auto& t : mesh.triangles) {
        for (int e = 0; e < 3; ++e) {
            const Vec3 a = mesh.positions[t[std::size_t(e)]], b = mesh.positions[t[std::size_t((e + 1) % 3)]];
            for (int k = 1; k < 8; ++k)
                rays.push_back({centre, glm::normalize(a + (Real(k) / 8) * (b - a) - centre)});
        }
    }
    // And in random directions, up to 10^5 rays in all.
    Pcg32 rng(5, 5);
    while (rays.size() < 100000) rays.push_back({centre, random_unit(rng)});
    REQUIRE(rays.size() >= 100000);

    Scene scene = scene_of({Shape{mesh, 0, "mesh"}});
    const World watertight(scene, {TriangleTest::kWatertight, Acceleration::kBvh});
    // The binary BVH tests its triangles one by one (the wide one four at a time, in packets).
    const World one_by_one(scene, {TriangleTest::kWatertight, Acceleration::kBinaryBvh});
    const World moller(scene, {TriangleTest::kMollerTrumbore, Acceleration::kBvh});
    CHECK(escaped(watertight, rays) == 0);
    CHECK(escaped(one_by_one, rays) == 0);
    const std::uint64_t moller_leaks = escaped(moller, rays);
    WARN("Möller–Trumbore: " << moller_leaks << " of " << rays.size() << " rays escaped the closed mesh");
    CHECK(moller_leaks > 0);  // the failure the watertight test exists to prevent
    // The leak probe of the executable sees the same.
    CHECK(probe_leaks(mesh, TriangleTest::kWatertight).escaped == 0);
}

TEST_CASE("A hit found in a triangle packet has the record of the triangle tested alone",
          "[world][ex:ch02.slab_widening][ex:ch02.triangle_watertight][ex:ch02.wide_bvh_traversal]") {
    // The same tree (the SAH counting triangles in both), its leaves tested one by one or in packets: the
    // packet's hit record reads the triangle's corners from the packet, the other from the triangle itself;
    // they must be the same bits. The mesh emits, so every triangle is a light: its number in scene order.
    const MeshShape mesh = jittered_closed_mesh(3);
    Scene scene = scene_of({Shape{mesh, 0, "mesh"}});
    scene.materials[0].emission = Color{1.0f};
    const World one_by_one(scene, {TriangleTest::kWatertight, Acceleration::kBvh, false, false});
    const World packets(scene, {TriangleTest::kWatertight, Acceleration::kBvh, true, false});
    Pcg32 rng(5, 21);
    for (int i = 0; i < 20000; ++i) {
        const Ray ray{Vec3{10.3f, -5.1f, 2.9f} + Real(0.5) * random_unit(rng), random_unit(rng)};
        const auto a = one_by_one.intersect(ray), b = packets.intersect(ray);
        REQUIRE(a.has_value());
        REQUIRE(b.has_value());
        INFO("ray " << i);
        CHECK(a->t == b->t);
        CHECK(a->point == b->point);
        CHECK(a->point_error == b->point_error);
        CHECK(a->normal == b->normal);
        CHECK(a->front_face == b->front_face);
        CHECK(a->primitive == b->primitive);
        CHECK(a->material == b->material);
        CHECK(b->light == std::int32_t(b->primitive));
        CHECK(a->light == b->light);
    }
}

TEST_CASE("Rays aimed exactly at a shared diagonal always hit one of its two triangles",
          "[stability][triangle][ex:ch02.triangle_moller][ex:ch02.triangle_watertight]") {
    Pcg32 rng(17, 3);
    std::uint64_t watertight_misses = 0, moller_misses = 0, rays = 0;
    for (int quad = 0; quad < 100; ++quad) {
        // A random, non-planar-to-axes quad p0 p1 p2 p3 split along p0–p2.
        auto random_point = [&] {
            return Vec3{rng.next_real(), rng.next_real(), rng.next_real()} * Real(20) - Real(10);
        };
        const Vec3 p0 = random_point(), p2 = random_point();
        const Vec3 side = random_point();
        const Vec3 p1 = p0 + (p2 - p0) * Real(0.5) + side * Real(0.3),
                   p3 = p0 + (p2 - p0) * Real(0.5) - side * Real(0.3);
        const Triangle a{p0, p1, p2}, b{p0, p2, p3};
        const Vec3 normal = glm::cross(p1 - p0, p2 - p0);
        if (glm::length(normal) < Real(1e-3)) continue;
        for (int i = 0; i < 100; ++i) {
            const Vec3 target = p0 + rng.next_real() * (p2 - p0);
            const Vec3 origin = target + glm::normalize(normal) * (Real(1) + Real(30) * rng.next_real()) +
                                random_point() * Real(0.5);
            const Ray ray{origin, glm::normalize(target - origin)};
            ++rays;
            const bool hit_watertight = intersect_triangle(ray, a, kInfinity, TriangleTest::kWatertight) ||
                                        intersect_triangle(ray, b, kInfinity, TriangleTest::kWatertight);
            const bool hit_moller = intersect_triangle(ray, a, kInfinity, TriangleTest::kMollerTrumbore) ||
                                    intersect_triangle(ray, b, kInfinity, TriangleTest::kMollerTrumbore);
            watertight_misses += hit_watertight ? 0 : 1;
            moller_misses += hit_moller ? 0 : 1;
        }
    }
    CHECK(rays > 9000);
    CHECK(watertight_misses == 0);
    WARN("Möller–Trumbore missed " << moller_misses << " of " << rays << " rays through the shared diagonal");
}

TEST_CASE("Parallel rays and degenerate triangles give no hit and nothing non-finite",
          "[stability][triangle][ex:ch02.triangle_moller][ex:ch02.triangle_watertight]") {
    const Triangle flat{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const Ray in_plane{{-1, 0.2f, 0}, {1, 0, 0}};        // slides through the triangle inside its plane
    const Ray above_plane{{-1, 0.2f, 0.5f}, {1, 0, 0}};  // parallel, off the plane
    const Triangle repeated{{0, 0, -1}, {0, 0, -1}, {1, 1, -1}};
    const Triangle collinear{{0, 0, -1}, {1, 1, -1}, {2, 2, -1}};
    const Triangle point{{0.5f, 0.5f, -1}, {0.5f, 0.5f, -1}, {0.5f, 0.5f, -1}};
    const Ray down{{0.5f, 0.5f, 0}, {0, 0, -1}};  // straight through the collinear and repeated vertices
    for (TriangleTest test : {TriangleTest::kWatertight, TriangleTest::kMollerTrumbore}) {
        CHECK_FALSE(intersect_triangle(in_plane, flat, kInfinity, test));
        CHECK_FALSE(intersect_triangle(above_plane, flat, kInfinity, test));
        CHECK_FALSE(intersect_triangle(down, repeated, kInfinity, test));
        CHECK_FALSE(intersect_triangle(down, collinear, kInfinity, test));
        CHECK_FALSE(intersect_triangle(down, point, kInfinity, test));
    }
    // Through the World too, where a degenerate triangle's normal must still be finite.
    const World world(scene_of({Shape{TriangleShape{{repeated.p0, repeated.p1, repeated.p2}}, 0, "r"},
                                Shape{TriangleShape{{collinear.p0, collinear.p1, collinear.p2}}, 0, "c"}}));
    CHECK_FALSE(world.intersect(down));
    CHECK(is_finite(triangle_normal(collinear)));
}

TEST_CASE("Tiny and huge triangles are hit at their centroid with barycentrics of one third",
          "[stability][triangle][ex:ch02.triangle_moller][ex:ch02.triangle_watertight]") {
    for (Real scale : {Real(1e-6), Real(1), Real(1e6)}) {
        const Triangle tri{Vec3{1, 0, 0} * scale, Vec3{0, 1, 0} * scale, Vec3{0, 0, 1} * scale};
        const Vec3 centroid = (tri.p0 + tri.p1 + tri.p2) / Real(3);
        const Vec3 normal = triangle_normal(tri);
        const Ray ray{centroid + normal * (Real(2) * scale), -normal};
        for (TriangleTest test : {TriangleTest::kWatertight, TriangleTest::kMollerTrumbore}) {
            const auto hit = intersect_triangle(ray, tri, kInfinity, test);
            INFO("scale " << scale
                          << (test == TriangleTest::kWatertight ? " watertight" : " Möller–Trumbore"));
            REQUIRE(hit);
            CHECK(hit->t == Approx(2 * scale).epsilon(1e-5));
            CHECK(hit->barycentrics.x == Approx(1.0 / 3).margin(1e-5));
            CHECK(hit->barycentrics.y == Approx(1.0 / 3).margin(1e-5));
        }
    }
}

TEST_CASE("Small far spheres are hit within a few ulps, while the textbook quadratic misses some",
          "[stability][sphere][ex:ch02.sphere_stable][ex:ch02.sphere_textbook]") {
    Pcg32 rng(23, 9);
    for (Real radius : {Real(0.1), Real(0.01)}) {
        for (Real distance : {Real(10), Real(400), Real(1e3), Real(1e4)}) {
            const Sphere sphere{{0.3f, -0.2f, 0.1f}, radius};
            int reference_hits = 0, robust_hits = 0, textbook_misses = 0, far_from_reference = 0;
            for (int i = 0; i < 1000; ++i) {
                // Aimed at a point up to 0.95 r off the centre, seen from `distance` along a random
                // direction.
                const Vec3 axis = random_unit(rng);
                const Vec3 side = glm::normalize(glm::cross(axis, random_unit(rng)));
                const Vec3 target = sphere.center + side * (Real(0.95) * radius * rng.next_real());
                const Ray ray{sphere.center + axis * distance,
                              glm::normalize(target - (sphere.center + axis * distance))};
                const double reference = reference_sphere_t(ray, sphere);
                if (reference < 0) continue;  // the rounded ray itself misses: nothing to compare
                ++reference_hits;
                const auto t = intersect_sphere(ray, sphere, kInfinity);
                if (t) {
                    ++robust_hits;
                    if (std::abs(double(*t) - reference) > 4 * double(ulp(Real(reference))))
                        ++far_from_reference;
                }
                const auto textbook = sphere_roots_textbook(ray, sphere);
                if (!textbook) ++textbook_misses;
            }
            INFO("radius " << radius << ", distance " << distance);
            CHECK(reference_hits > 900);
            CHECK(robust_hits == reference_hits);
            CHECK(far_from_reference == 0);
            if (distance >= Real(1e3)) CHECK(textbook_misses > 0);  // b² − c₀ has lost every digit of Δ
            WARN("radius " << radius << " at " << distance << ": textbook quadratic missed "
                           << textbook_misses << " of " << reference_hits);
        }
    }
}

TEST_CASE("Huge spheres, origins at the centre, inside and on the surface, tangents and poles",
          "[stability][sphere][ex:ch02.sphere_stable][ex:ch02.sphere_textbook]") {
    SECTION("origins 1e-3 outside a sphere of radius 1e4") {
        // c₀ = |f|² − r² ≈ 20 is the difference of two numbers near 1e8, where floats are 8 apart: the
        // textbook form rounds it (and b² − c₀) to multiples of 8, and −b − √Δ then cancels.
        const Sphere huge{{0, 0, 0}, 1e4f};
        Pcg32 rng(3, 3);
        double stable_error = 0, textbook_error = 0;
        int outside = 0;
        for (int i = 0; i < 100; ++i) {
            const Vec3 axis = random_unit(rng);
            const Ray ray{axis * (1e4f + 1e-3f), -axis};
            if (!(glm::length(Vec3d(ray.origin)) > 1e4)) continue;  // rounding put this origin inside
            ++outside;
            const double exact_t0 = reference_sphere_t(ray, huge);
            const auto stable = sphere_roots_stable(ray, huge);
            const auto textbook = sphere_roots_textbook(ray, huge);
            REQUIRE(stable);
            stable_error = std::max(stable_error, std::abs(double(stable->t0) - exact_t0) / exact_t0);
            textbook_error = std::max(textbook_error,
                                      textbook ? std::abs(double(textbook->t0) - exact_t0) / exact_t0 : 1.0);
        }
        WARN("near root, largest relative error: stable " << stable_error << ", textbook " << textbook_error);
        CHECK(outside > 20);
        CHECK(stable_error < 1e-4);
        CHECK(textbook_error > 0.1);
    }
    SECTION("origin at the centre and inside: the far root") {
        const Sphere sphere{{1, 2, 3}, 2};
        const auto centre = intersect_sphere(Ray{{1, 2, 3}, {0, 1, 0}}, sphere, kInfinity);
        REQUIRE(centre);
        CHECK(*centre == Approx(2));
        const auto inside = intersect_sphere(Ray{{1, 2, 4}, {0, 0, 1}}, sphere, kInfinity);
        REQUIRE(inside);
        CHECK(*inside == Approx(1));
        const World world(scene_of({Shape{SphereShape{{1, 2, 3}, 2}, 0, "s"}}));
        const auto hit = world.intersect(Ray{{1, 2, 4}, {0, 0, 1}});
        REQUIRE(hit);
        CHECK_FALSE(hit->front_face);
        CHECK(hit->normal.z == Approx(-1));
    }
    SECTION("tangent rays touch the sphere once") {
        const Sphere sphere{{0, 0, 0}, 1};
        const auto roots = sphere_roots_stable(Ray{{1, 0, -10}, {0, 0, 1}}, sphere);
        REQUIRE(roots);
        CHECK(roots->t0 == Approx(10));
        CHECK(roots->t1 == Approx(10));
        CHECK_FALSE(sphere_roots_stable(Ray{{1.001f, 0, -10}, {0, 0, 1}}, sphere));
    }
    SECTION("a hit exactly at a pole has a finite normal") {
        const World world(scene_of({Shape{SphereShape{{0, 0, 0}, 1}, 0, "s"}}));
        for (Real direction : {Real(-1), Real(1)}) {
            const auto hit = world.intersect(Ray{{0, -5 * direction, 0}, {0, direction, 0}});
            REQUIRE(hit);
            CHECK(finite_hit(*hit));
            CHECK(hit->t == Approx(4));
            CHECK(std::abs(hit->normal.y) == Approx(1));
        }
    }
}

TEST_CASE("Hit points carry an error bound that contains the exact surface point",
          "[stability][world][ex:ch02.quad_packet][ex:ch02.sphere_stable]"
          "[ex:ch02.triangle_watertight]") {
    Pcg32 rng(31, 2);
    std::vector<Shape> shapes;
    shapes.push_back({SphereShape{{1000.5f, -300.25f, 77.7f}, 13.3f}, 0, "sphere"});
    shapes.push_back({QuadShape{{900, -400, 50}, {200, 10, 0}, {0, 30, 200}}, 0, "quad"});
    shapes.push_back(
        {TriangleShape{{Vec3{950, -350, 60}, Vec3{1100, -340, 70}, Vec3{1000, -200, 90}}}, 0, "tri"});
    const World world(scene_of(shapes));
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 origin = Vec3{1000, -300, 80} + random_unit(rng) * Real(500);
        const Vec3 target = Vec3{1000, -300, 80} + random_unit(rng) * Real(40);
        const Ray ray{origin, glm::normalize(target - origin)};
        const auto hit = world.intersect(ray);
        if (!hit) continue;
        ++checked;
        // Distance of the point from the shape's exact surface, in double, against the bound along the
        // normal.
        const Vec3d p{hit->point};
        double distance = 0;
        if (hit->primitive == 0) {
            distance = std::abs(glm::length(p - Vec3d(1000.5f, -300.25f, 77.7f)) - double(13.3f));
        } else {
            const Vec3d a = hit->primitive == 1 ? Vec3d(900, -400, 50) : Vec3d(950, -350, 60);
            const Vec3d n = hit->primitive == 1
                                ? glm::normalize(glm::cross(Vec3d(200, 10, 0), Vec3d(0, 30, 200)))
                                : glm::normalize(glm::cross(Vec3d(150, 10, 10), Vec3d(50, 150, 30)));
            distance = std::abs(glm::dot(p - a, n));
        }
        const double bound = glm::length(Vec3d(hit->point_error));
        if (!(distance <= bound))
            FAIL("primitive " << hit->primitive << ": off the surface by " << distance << ", bound "
                              << bound);
    }
    CHECK(checked > 1000);
}

TEST_CASE("The slab test handles zero direction components of either sign and flat boxes",
          "[stability][bvh][ex:ch02.slab_test][ex:ch02.slab_widening]") {
    const Aabb box{{0, 0, 0}, {1, 1, 1}};
    for (Real zero : {Real(0), -Real(0)}) {
        INFO("zero component " << zero);
        CHECK(hits_box(box, Ray{{0.5f, 0.5f, -1}, {zero, zero, 1}}, kInfinity));
        CHECK_FALSE(hits_box(box, Ray{{1.5f, 0.5f, -1}, {zero, 0, 1}}, kInfinity));
        CHECK_FALSE(hits_box(box, Ray{{-0.5f, 0.5f, -1}, {zero, 0, 1}}, kInfinity));
        CHECK(hits_box(box, Ray{{1, 0.5f, -1}, {zero, 0, 1}}, kInfinity));  // on the face x = 1
        CHECK(hits_box(box, Ray{{0, 1, -1}, {zero, zero, 1}}, kInfinity));  // along an edge
    }
    CHECK(slab_entry(box, Ray{{0.5f, 0.5f, 0.5f}, {0, 0, 1}}, inverse_direction({0, 0, 1}), kInfinity) == 0);
    CHECK(slab_entry(box, Ray{{0.5f, 0.5f, -2}, {0, 0, 1}}, inverse_direction({0, 0, 1}), kInfinity) ==
          Approx(2));
    CHECK_FALSE(hits_box(box, Ray{{0.5f, 0.5f, -2}, {0, 0, 1}}, 1));  // ends before the box
    const Aabb flat{{0, 0, 0.5f}, {1, 1, 0.5f}};
    CHECK(hits_box(flat, Ray{{0.25f, 0.75f, -3}, {0, 0, 1}}, kInfinity));
    CHECK(hits_box(flat, Ray{{0.25f, 0.75f, 7}, {0, 0, -1}}, kInfinity));
    CHECK(hits_box(flat, Ray{{-1, 0.5f, 0.5f}, {1, 0, 0}}, kInfinity));  // inside the flat slab
    CHECK_FALSE(hits_box(flat, Ray{{-1, 0.5f, 0.6f}, {1, 0, 0}}, kInfinity));
    const Ray diagonal{{-1, -1, -0.5f},
                       glm::normalize(Vec3{1, 1, 1})};  // crosses the flat box's plane at (0,0)
    CHECK(hits_box(flat, diagonal, kInfinity));
}

TEST_CASE("The BVH finds the same nearest hit as testing every primitive",
          "[stability][bvh][ex:ch02.bvh_traversal][ex:ch02.quad][ex:ch02.quad_packet][ex:ch02.slab_test]"
          "[ex:ch02.slab_widening][ex:ch02.sphere_stable][ex:ch02.triangle_watertight]"
          "[ex:ch02.wide_bvh_traversal]") {
    Pcg32 rng(41, 7);
    std::vector<Shape> shapes;
    auto random_point = [&](Real size) {
        return Vec3{rng.next_real(), rng.next_real(), rng.next_real()} * (2 * size) - size;
    };
    for (int i = 0; i < 300; ++i) {
        const Vec3 c = random_point(50);
        switch (i % 3) {
            case 0:
                shapes.push_back({SphereShape{c, Real(0.5) + 3 * rng.next_real()}, 0, "s"});
                break;
            case 1:
                shapes.push_back({QuadShape{c, random_point(4), random_point(4)}, 0, "q"});
                break;
            default:
                shapes.push_back({TriangleShape{{c, c + random_point(5), c + random_point(5)}}, 0, "t"});
                break;
        }
    }
    shapes.push_back({make_icosphere(3), 0, "mesh"});
    for (Vec3& p : std::get<MeshShape>(shapes.back().geometry).positions) p = p * Real(20);
    const Scene scene = scene_of(shapes);
    // The wide BVH the World traces through by default, and the binary one it is collapsed from.
    const World bvh(scene, {TriangleTest::kWatertight, Acceleration::kBvh});
    const World binary(scene, {TriangleTest::kWatertight, Acceleration::kBinaryBvh});
    const World brute(scene, {TriangleTest::kWatertight, Acceleration::kNone});
    int mismatches = 0, occlusion_mismatches = 0, nearest_mismatches = 0, hits = 0;
    for (int i = 0; i < 100000; ++i) {
        const Vec3 origin = random_point(80);
        const Ray ray{origin, glm::normalize(random_point(50) - origin)};
        const Real t_max = rng.next_real() < Real(0.5) ? kInfinity : Real(100) * rng.next_real();
        const auto b = brute.intersect(ray, t_max);
        for (const World* world : {&bvh, &binary}) {
            const auto a = world->intersect(ray, t_max);
            if (a.has_value() != b.has_value() || (a && (a->t != b->t || a->primitive != b->primitive)))
                ++mismatches;
            if (world->occluded(ray, t_max) != b.has_value()) ++occlusion_mismatches;
            const auto n = world->nearest(ray, t_max);
            if (n.has_value() != a.has_value() || (n && (n->t != a->t || n->primitive != a->primitive)))
                ++nearest_mismatches;
        }
        hits += b ? 1 : 0;
    }
    CHECK(hits > 5000);  // a quarter of the rays or so hit the torus
    CHECK(mismatches == 0);
    CHECK(occlusion_mismatches == 0);
    CHECK(nearest_mismatches == 0);
}

namespace {

// A random point of the box [-1, 1]³ scaled by `size` about `center`, in double so that neither a tiny size
// (1e-40, below float's normal range) nor a huge one loses the point.
Vec3 point_near(Pcg32& rng, const Vec3d& center, double size) {
    const Vec3d u{rng.next_real(), rng.next_real(), rng.next_real()};
    return Vec3(center + (u * 2.0 - 1.0) * size);
}

// `count` rays from around the soup's box toward points inside it: their direction is normalised in double
// (float's length of a 1e-40 vector underflows to zero), half of them with a t_max inside the box.
std::vector<BvhQuery> rays_at(Pcg32& rng, const Vec3d& center, double size, int count) {
    std::vector<BvhQuery> queries;
    for (int i = 0; i < count; ++i) {
        const Vec3 origin = point_near(rng, center, 3 * size);
        const Vec3d d = Vec3d(point_near(rng, center, size)) - Vec3d(origin);
        const Real t_max = i % 2 ? kInfinity : Real(3 * size * double(rng.next_real()));
        if (glm::length(d) > 0) queries.push_back({Ray{origin, Vec3(glm::normalize(d))}, t_max});
    }
    return queries;
}

// The soup's BVH: built without a fault, every primitive once in boxes containing their children, and every
// ray answered as by testing every triangle. Returns how many rays hit something (brute force).
int check_soup(const std::vector<Vec3>& corners, std::span<const BvhQuery> queries) {
    const Scene scene = triangle_soup(corners);
    std::vector<Aabb> boxes;
    for (std::size_t i = 0; i + 2 < corners.size(); i += 3) {
        Aabb b;
        for (std::size_t k = 0; k < 3; ++k) b.extend(corners[i + k]);
        boxes.push_back(b);
    }
    std::vector<std::uint32_t> order;
    const Bvh bvh(boxes, order);
    check_hierarchy(bvh, boxes, order);
    const auto disagreement = first_bvh_disagreement(scene, queries);
    INFO((disagreement ? *disagreement : std::string("every ray agrees")));
    CHECK_FALSE(disagreement);
    const World brute(scene, {TriangleTest::kWatertight, Acceleration::kNone});
    int hits = 0;
    for (const BvhQuery& q : queries) hits += brute.intersect(q.ray, q.t_max) ? 1 : 0;
    return hits;
}

}  // namespace

TEST_CASE("The BVH builds over degenerate sets: all in one point, on one plane, on one line",
          "[stability][bvh][ex:ch02.bvh_traversal][ex:ch02.slab_test][ex:ch02.slab_widening]"
          "[ex:ch02.triangle_watertight]"
          "[ex:ch02.wide_bvh_traversal]") {
    Pcg32 rng(3, 14);
    const Vec3d center{0.5, -2, 7};
    std::vector<Vec3> point(3 * 600, Vec3(center));
    std::vector<Vec3> plane, line, across_line;
    for (int i = 0; i < 3 * 600; ++i) {
        Vec3 p = point_near(rng, center, 4);
        p.z = Real(center.z);
        plane.push_back(p);
        line.push_back(Vec3(center) + Vec3(rng.next_real() * 8, 0, 0));
    }
    for (int i = 0; i < 600; ++i) {  // triangles across the x axis: their centroids all on one line
        const Vec3 c = Vec3(center) + Vec3(rng.next_real() * 8, 0, 0);
        across_line.insert(across_line.end(), {c + Vec3(0, -1, -1), c + Vec3(0, 1, -1), c + Vec3(0, 0, 1)});
    }
    SECTION("one point: nothing is ever hit") { CHECK(check_soup(point, rays_at(rng, center, 4, 2000)) == 0); }
    SECTION("one plane") { CHECK(check_soup(plane, rays_at(rng, center, 4, 4000)) > 400); }
    SECTION("one line: no triangle has an area") { CHECK(check_soup(line, rays_at(rng, center, 4, 2000)) == 0); }
    SECTION("centroids on one line") { CHECK(check_soup(across_line, rays_at(rng, center, 4, 4000)) > 200); }
}

TEST_CASE("The BVH culls no box it should enter, at every scale from 1e-40 to 1e30 and across them",
          "[stability][bvh][ex:ch02.bvh_traversal][ex:ch02.slab_test][ex:ch02.slab_widening]"
          "[ex:ch02.wide_bvh_traversal]") {
    Pcg32 rng(5, 40);
    // `count` boxes near `center`, each of size 10^e for e drawn from [low, high].
    auto boxes_near = [&](const Vec3d& center, double spread, double low, double high, int count) {
        std::vector<Aabb> boxes;
        for (int i = 0; i < count; ++i) {
            const Vec3 c = point_near(rng, center, spread);
            const double size = std::pow(10.0, low + (high - low) * double(rng.next_real()));
            Aabb b;
            for (int k = 0; k < 2; ++k) b.extend(Vec3(Vec3d(c) + Vec3d(point_near(rng, Vec3d(0), size))));
            boxes.push_back(b);
        }
        return boxes;
    };
    // Boxes as primitives, hit at their exact entry: the BVH must return exactly the brute-force minimum.
    auto check = [&](const std::vector<Aabb>& boxes, std::span<const BvhQuery> queries) {
        std::vector<std::uint32_t> order;
        check_hierarchy(Bvh(boxes, order), boxes, order);
        const auto disagreement = first_box_disagreement(boxes, queries);
        INFO((disagreement ? *disagreement : std::string("every ray agrees")));
        CHECK_FALSE(disagreement);
    };
    for (const double scale : {1e-44, 1e-40, 1e-30, 1e-20, 1e-5, 1e5, 1e20, 1e30}) {
        INFO("boxes of size " << scale << " in a cloud 10 times that");
        check(boxes_near(Vec3d(0), 10 * scale, std::log10(scale), std::log10(scale), 700),
              rays_at(rng, Vec3d(0), 10 * scale, 2000));
        INFO("the same 1e6 sizes away from the origin");
        check(boxes_near(Vec3d(1e6 * scale), 10 * scale, std::log10(scale), std::log10(scale), 700),
              rays_at(rng, Vec3d(1e6 * scale), 10 * scale, 2000));
    }
    // Sizes from 1e-30 to 1e30 in one cloud, rays aimed at the cloud and at some of its tiny boxes.
    const auto mixed = boxes_near(Vec3d(0), 1e30, -30, 30, 1500);
    auto queries = rays_at(rng, Vec3d(0), 1e30, 2000);
    for (std::size_t i = 0; i < mixed.size() && i < 300; ++i) {
        const Vec3d c = (Vec3d(mixed[i].min) + Vec3d(mixed[i].max)) / 2.0;
        const auto near = rays_at(rng, c, glm::length(Vec3d(mixed[i].max) - Vec3d(mixed[i].min)), 3);
        queries.insert(queries.end(), near.begin(), near.end());
    }
    check(mixed, queries);
    // Rays whose direction has a subnormal x (float's 1 / d_x overflows), starting a few subnormals short of
    // the face x = 0 every box starts at: they enter the boxes at t = (0 − o_x) / d_x, about 1e-5.
    auto at_face = boxes_near(Vec3d(0), 10, -1, 1, 1500);
    for (Aabb& b : at_face) b.min.x = 0, b.max.x = std::abs(b.max.x) + 1;
    std::vector<BvhQuery> nearly_parallel;
    for (int i = 0; i < 2000; ++i) {
        Vec3 origin = point_near(rng, Vec3d(0), 12);
        origin.x = -std::numeric_limits<Real>::denorm_min() * Real(1 + i % 64);
        const Vec3 d{Real(1e-40) * (1 + rng.next_real()), rng.next_real() - Real(0.5), 1};
        nearly_parallel.push_back({Ray{origin, d}, kInfinity});
    }
    check(at_face, nearly_parallel);
}

TEST_CASE("Triangle soups from 1e-14 to 1e12 get the brute-force nearest hit through the BVH",
          "[stability][bvh][ex:ch02.bvh_traversal][ex:ch02.slab_test][ex:ch02.slab_widening]"
          "[ex:ch02.triangle_watertight]"
          "[ex:ch02.wide_bvh_traversal]") {
    Pcg32 rng(6, 12);
    for (const double scale : {1e-14, 1e-12, 1e-6, 1.0, 1e6, 1e12}) {
        INFO("triangles of size " << scale << " in a cloud 10 times that");
        std::vector<Vec3> corners;
        for (int i = 0; i < 800; ++i) {
            const Vec3 c = point_near(rng, Vec3d(0), 10 * scale);
            for (int k = 0; k < 3; ++k) corners.push_back(Vec3(Vec3d(c) + Vec3d(point_near(rng, Vec3d(0), scale))));
        }
        CHECK(check_soup(corners, rays_at(rng, Vec3d(0), 10 * scale, 3000)) > 300);
    }
}

TEST_CASE(
    "A triangle 1e-14 from the ray's origin: T's products fall among subnormals, and t found in double holds",
    "[stability][triangle][ex:ch02.triangle_watertight]") {
    // The scaled distance T = U z'_a + V z'_b + W z'_c is a product of three coordinates: at 1e-14 it is
    // about 1e-42, below float's normal range (1.2e-38), where rounding is absolute. The naive product shows
    // it.
    const Real c = Real(2e-15);
    const double exact = double(c) * double(c) * double(c);
    CHECK(std::abs(double(c * c * c) - exact) > 1e-2 * exact);  // 5 % off, where float's u is 6e-8
    // The fuzzer found two triangles meeting at a corner on the ray, 2.44e-14 from its origin, hit at
    // distances 0.8 % apart: beyond each hit's error bound, so the wide BVH culled the nearer. In double
    // both are hit at the corner's distance.
    const Real a = Real(-4.65335803e-15), v = Real(-1.87248898e-14);
    const Ray diagonal{Vec3(a), glm::normalize(Vec3(-1))};
    const double corner_distance = (double(a) - double(v)) / -double(diagonal.direction.x);
    for (const Triangle& tri :
         {Triangle{Vec3{a, Real(-2.57647920e-15), a}, Vec3{a, Real(-1.86134321e-14), v}, Vec3(v)},
          Triangle{Vec3{0, v, Real(-1.86134321e-14)}, Vec3(v), Vec3{Real(-9.36244490e-15), v, v}}}) {
        const auto hit = intersect_triangle(diagonal, tri, kInfinity, TriangleTest::kWatertight);
        REQUIRE(hit);
        CHECK(std::abs(double(hit->t) - corner_distance) < 1e-6 * corner_distance);
    }
    // Random triangles and rays at 1e-13 to 1e-15: t within 1e-5 of the exact distance to the plane,
    // and the packet's lanes give the same hit bit for bit.
    Pcg32 rng(9, 14);
    int hits = 0;
    for (const double scale : {1e-13, 1e-14, 1e-15}) {
        for (int trial = 0; trial < 2000; ++trial) {
            const Triangle tri{point_near(rng, Vec3d(0), scale), point_near(rng, Vec3d(0), scale),
                               point_near(rng, Vec3d(0), scale)};
            const Vec3d p0(tri.p0), e1 = Vec3d(tri.p1) - p0, e2 = Vec3d(tri.p2) - p0;
            const Vec3d target = p0 + 0.3 * e1 + 0.3 * e2;  // well inside
            const Vec3 origin = point_near(rng, Vec3d(0), 3 * scale);
            const Ray ray{origin, Vec3(glm::normalize(target - Vec3d(origin)))};
            const Vec3d n = glm::cross(e1, e2);
            const double t_plane = glm::dot(n, p0 - Vec3d(origin)) / glm::dot(n, Vec3d(ray.direction));
            const WatertightRay sheared = make_watertight_ray(ray);
            const auto hit = intersect_triangle_watertight(ray, sheared, tri, kInfinity);
            const Triangle packed[] = {tri};
            const std::uint32_t slot[] = {0};
            const auto lane =
                intersect_triangle_packet(ray, sheared, make_triangle_packet(packed, slot), kInfinity);
            INFO("scale " << scale << ", trial " << trial);
            REQUIRE(hit.has_value() == lane.has_value());
            if (!hit) continue;
            ++hits;
            CHECK(lane->hit.t == hit->t);
            CHECK(lane->hit.barycentrics == hit->barycentrics);
            // A grazing ray's distance is ill-conditioned (rounding d moves it by about u / |cos θ|): not
            // compared.
            if (std::abs(glm::dot(glm::normalize(n), Vec3d(ray.direction))) > 0.05) {
                CHECK(std::abs(double(hit->t) - t_plane) < 1e-5 * t_plane);
            }
        }
    }
    CHECK(hits > 5000);
}

TEST_CASE("A triangle packet gives the watertight test's nearest hit bit for bit, on hard cases too",
          "[stability][triangle][ex:ch02.triangle_watertight]") {
    Pcg32 rng(5, 12);
    auto random_vector = [&](Real size) {
        return Vec3{rng.next_real(), rng.next_real(), rng.next_real()} * (2 * size) - size;
    };
    // Ordinary, degenerate (a repeated corner, three collinear corners), huge and tiny triangles, and fans
    // around one corner that share their edges (a ray through an edge meets two of them at one distance).
    auto random_triangles = [&](int count) {
        std::vector<Triangle> triangles;
        const Vec3 hub = random_vector(2);
        Vec3 previous = hub + random_vector(1);
        for (int i = 0; i < count; ++i) {
            const Vec3 a = random_vector(2), b = random_vector(1);
            switch (rng.next_uint() % 6) {
                case 0: triangles.push_back({a, a, a + b}); break;
                case 1: triangles.push_back({a, a + b, a + Real(2) * b}); break;
                case 2: triangles.push_back({a * Real(1e4), a * Real(1e4) + random_vector(Real(1e5)),
                                             a * Real(1e4) + random_vector(Real(1e5))}); break;
                case 3: triangles.push_back({a, a + random_vector(Real(1e-4)), a + random_vector(Real(1e-4))});
                    break;
                default: {
                    const Vec3 next = hub + random_vector(1);
                    triangles.push_back({hub, previous, next});
                    previous = next;
                }
            }
        }
        return triangles;
    };
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    int compared = 0, hit_packets = 0, mismatches = 0;
    for (int trial = 0; trial < 200000; ++trial) {
        const int count = 1 + int(rng.next_uint() % kTriangleLanes);  // partly filled packets too
        const std::vector<Triangle> triangles = random_triangles(count);
        std::vector<std::uint32_t> slots(triangles.size());
        for (std::uint32_t i = 0; i < slots.size(); ++i) slots[i] = 10 + i;
        const TrianglePacket packet = make_triangle_packet(triangles, slots);
        // Rays from anywhere, along an axis, or aimed at a corner or an edge of the first triangle.
        Ray ray{random_vector(4), glm::normalize(random_vector(1))};
        const int aim = int(rng.next_uint() % 4);
        if (aim == 1) ray.direction = axes[rng.next_uint() % 3] * (rng.next_uint() % 2 ? Real(1) : Real(-1));
        if (aim >= 2) {
            const Triangle& t = triangles[0];
            const Vec3 target = aim == 2 ? t.p1 : t.p0 + rng.next_real() * (t.p1 - t.p0);
            if (!(glm::length(target - ray.origin) > 0)) continue;
            ray.direction = glm::normalize(target - ray.origin);
        }
        const Real t_max = rng.next_real() < Real(0.5) ? kInfinity : Real(8) * rng.next_real();
        const WatertightRay sheared = make_watertight_ray(ray);
        std::optional<TrianglePacketHit> expected;
        for (int lane = 0; lane < count; ++lane) {
            const auto h = intersect_triangle_watertight(ray, sheared, triangles[std::size_t(lane)], t_max);
            if (h && (!expected || h->t < expected->hit.t)) expected = TrianglePacketHit{lane, *h};
        }
        const auto found = intersect_triangle_packet(ray, sheared, packet, t_max);
        ++compared;
        hit_packets += expected ? 1 : 0;
        const bool same =
            found.has_value() == expected.has_value() &&
            (!found || (found->lane == expected->lane && found->hit.t == expected->hit.t &&
                        found->hit.barycentrics == expected->hit.barycentrics &&
                        packet.slot[std::size_t(found->lane)] == 10 + std::uint32_t(found->lane)));
        if (!same) ++mismatches;
    }
    INFO(compared << " packets, " << hit_packets << " hit");
    CHECK(hit_packets > compared / 10);
    CHECK(mismatches == 0);
}

TEST_CASE("A quad packet gives intersect_quad's nearest hit bit for bit, on hard cases too",
          "[stability][quad][ex:ch02.quad][ex:ch02.quad_packet]") {
    Pcg32 rng(5, 11);
    auto random_vector = [&](Real size) {
        return Vec3{rng.next_real(), rng.next_real(), rng.next_real()} * (2 * size) - size;
    };
    // Ordinary, degenerate (u ∥ v or u = 0), huge and tiny quads; and axis-aligned quads, hit on their edges.
    auto random_quad = [&](int kind) {
        const Vec3 origin = random_vector(2);
        switch (kind) {
            case 0:
                return make_quad(origin, Vec3{0}, random_vector(1));
            case 1: {
                const Vec3 u = random_vector(1);
                return make_quad(origin, u, Real(2) * u);
            }
            case 2:
                return make_quad(origin * Real(1e4), random_vector(Real(1e5)), random_vector(Real(1e5)));
            case 3:
                return make_quad(origin, random_vector(Real(1e-4)), random_vector(Real(1e-4)));
            case 4:
                return make_quad(Vec3{-1, -1, origin.z}, {2, 0, 0}, {0, 2, 0});
            default:
                return make_quad(origin, random_vector(1), random_vector(1));
        }
    };
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    int compared = 0, hit_packets = 0, mismatches = 0;
    for (int trial = 0; trial < 200000; ++trial) {
        std::vector<Quad> quads;
        const int count = 1 + int(rng.next_uint() % kQuadLanes);  // partly filled packets too
        for (int i = 0; i < count; ++i) quads.push_back(random_quad(int(rng.next_uint() % 8)));
        std::vector<std::uint32_t> indices(quads.size());
        for (std::uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
        const QuadPacket packet = make_quad_packet(quads, indices);
        // Rays from anywhere, along an axis (zero components: parallel to axis-aligned quads, or lying in
        // their plane), or aimed at an edge or a corner of the first quad (a or b exactly 0 or 1).
        Ray ray{random_vector(4), glm::normalize(random_vector(1))};
        const int aim = int(rng.next_uint() % 4);
        if (aim == 1) ray.direction = axes[rng.next_uint() % 3] * (rng.next_uint() % 2 ? Real(1) : Real(-1));
        if (aim >= 2) {
            const Quad& q = quads[0];
            const Real a = aim == 2 ? rng.next_real() : Real(rng.next_uint() % 2);
            const Vec3 target = q.origin + a * q.u + Real(rng.next_uint() % 2) * q.v;
            if (!(glm::length(target - ray.origin) > 0)) continue;
            ray.direction = glm::normalize(target - ray.origin);
        }
        const Real t_max = rng.next_real() < Real(0.5) ? kInfinity : Real(8) * rng.next_real();
        std::optional<PacketHit> expected;
        for (int lane = 0; lane < count; ++lane) {
            const auto h = intersect_quad(ray, quads[std::size_t(lane)], t_max);
            if (h && (!expected || h->t < expected->hit.t)) expected = PacketHit{lane, *h};
        }
        const auto found = intersect_quad_packet(ray, packet, t_max);
        ++compared;
        hit_packets += expected ? 1 : 0;
        const bool same = found.has_value() == expected.has_value() &&
                          (!found || (found->lane == expected->lane && found->hit.t == expected->hit.t &&
                                      found->hit.ab == expected->hit.ab));
        if (!same) ++mismatches;
    }
    INFO(compared << " packets, " << hit_packets << " hit");
    CHECK(hit_packets > compared / 10);
    CHECK(mismatches == 0);
}

TEST_CASE("The wide BVH visits the nearest leaf first and culls every child entered beyond the nearest hit",
          "[bvh][ex:ch02.slab_widening][ex:ch02.wide_bvh_traversal]") {
    // 256 unit boxes in a row along x, 2 apart, and a ray along the row from x = -10: box i is "hit" where
    // the ray crosses its face x = 2i, at t = 2i + 10, never before its box is entered. Nearest first, the
    // leaf of box 0 is tested first and every other child is entered after its hit, at t >= 12: that leaf's
    // items are the only ones tested (a child visited out of order, or popped without the t_max test, adds
    // items). Then a ray from x = 509.5, between the last two boxes (inside the tree's bounds, where the walk
    // gathers the entered children without a branch), back along the row: box i is hit where it crosses
    // the face x = 2i + 1, at t = 508.5 − 2i, box 254 first, at t = 0.5; nearest first, only its leaf.
    std::vector<Aabb> boxes;
    for (int i = 0; i < 256; ++i) {
        Aabb b;
        b.extend(Vec3(Real(2 * i), 0, 0));
        b.extend(Vec3(Real(2 * i + 1), 1, 1));
        boxes.push_back(b);
    }
    std::vector<std::uint32_t> order;
    const Bvh bvh(boxes, order);
    const WideBvh wide(bvh);
    auto leaf_of = [&](std::uint32_t box) {  // the item count of the leaf holding `box`
        std::uint32_t items = 0;
        for (const WideBvhNode& node : wide.nodes())
            for (std::size_t k = 0; k < std::size_t(kWideBvhWidth); ++k)
                for (std::uint32_t slot = node.child[k]; slot < node.child[k] + node.count[k]; ++slot)
                    if (order[slot] == box) items = node.count[k];
        return items;
    };
    struct Case {
        Real origin_x, direction_x;
        std::uint32_t nearest_box;
        Real t;
    };
    for (const Case c : {Case{-10, 1, 0, 10}, Case{Real(509.5), -1, 254, Real(0.5)}}) {
        const std::uint32_t first_leaf = leaf_of(c.nearest_box);
        REQUIRE(first_leaf > 0);
        const WideRay ray = make_wide_ray(
            {Vec3(c.origin_x, Real(0.5), Real(0.5)), glm::normalize(Vec3(c.direction_x, Real(1e-4), Real(1e-4)))});
        REQUIRE(ray.finite);
        CHECK(wide.bounds().contains(ray.ray.origin) == (c.origin_x > 0));
        auto test = [&](std::uint32_t first, std::uint32_t count, Real& limit) {
            bool hit = false;
            for (std::uint32_t slot = first; slot < first + count; ++slot) {
                const Aabb& b = boxes[order[slot]];
                const Real t = ((c.direction_x > 0 ? b.min.x : b.max.x) - ray.ray.origin.x) * ray.inverse_d.x;
                if (t > 0 && t < limit) limit = t, hit = true;
            }
            return hit;
        };
        // An any-hit query takes the entered children in their order: from inside the row, the first leaf it
        // tests may be any of those ahead.
        for (const bool any_hit : {false, true}) {
            if (any_hit && c.origin_x > 0) continue;
            Real t_max = kInfinity;
            TraversalStats stats;
            CHECK(wide.traverse(ray, t_max, any_hit, test, &stats));
            CHECK(t_max == Approx(c.t).epsilon(1e-5));
            CHECK(stats.primitives == first_leaf);
        }
    }
}

TEST_CASE("Texture coordinates of a sphere follow pbrt's (phi, theta) about the y axis",
          "[uv][sphere][ex:ch02.sphere_stable]") {
    CHECK(sphere_uv({1, 0, 0}) == Vec2{0, 0.5f});  // φ = 0 on +x, the equator at v = ½
    CHECK(sphere_uv({0, 0, 1}).x == Approx(0.25));
    CHECK(sphere_uv({-1, 0, 0}).x == Approx(0.5));
    CHECK(sphere_uv({0, 0, -1}).x == Approx(0.75));
    CHECK(sphere_uv({0, 1, 0}).y == 1);  // the top pole
    CHECK(sphere_uv({0, -1, 0}).y == 0);
    const Real s = std::sqrt(Real(0.5));
    CHECK(sphere_uv({s, s, 0}).y == Approx(0.75));  // θ = 45°
    // Through the world: only a textured sphere's hit record pays for them.
    std::vector<Shape> shapes{{SphereShape{{0, 0, 0}, 2}, 0, "s"}};
    Scene scene = scene_of(shapes);
    const Ray down{{0, 5, 0}, {0, -1, 0}};
    CHECK(World(scene).intersect(down)->uv == Vec2d{0});
    scene.materials[0].textures = {{&Material::albedo, TextureDesc{CheckerDesc{}, Color(0.5f)}}};
    const auto top = World(scene).intersect(down);
    REQUIRE(top);
    CHECK(top->uv.y == 1);
    const auto side = World(scene).intersect(Ray{{0, 0, 5}, {0, 0, -1}});
    REQUIRE(side);
    CHECK(side->uv.x == Approx(0.25));
    CHECK(side->uv.y == Approx(0.5));
}

TEST_CASE("Texture coordinates of a quad, a box's faces, a triangle and a plane",
          "[uv][world][ex:ch02.plane][ex:ch02.quad][ex:ch02.quad_packet][ex:ch02.triangle_watertight]") {
    for (Acceleration accel : {Acceleration::kBvh, Acceleration::kNone}) {
        // A quad's (a, b) of origin + a u + b v.
        std::vector<Shape> quad{{QuadShape{{-1, -1, -5}, {4, 0, 0}, {0, 2, 0}}, 0, "q"}};
        const auto q = World(scene_of(quad), {TriangleTest::kWatertight, accel})
                           .intersect(Ray{{0, 0.5f, 0}, {0, 0, -1}});
        REQUIRE(q);
        CHECK(q->uv == Vec2d{0.25f, 0.75f});
        // A triangle's barycentrics (b1, b2) of its second and third vertices.
        std::vector<Shape> triangle{
            {TriangleShape{{Vec3{0, 0, -5}, Vec3{4, 0, -5}, Vec3{0, 4, -5}}}, 0, "t"}};
        const auto t = World(scene_of(triangle), {TriangleTest::kWatertight, accel})
                           .intersect(Ray{{1, 2, 0}, {0, 0, -1}});
        REQUIRE(t);
        CHECK(t->uv.x == Approx(0.25));
        CHECK(t->uv.y == Approx(0.5));
        // A box: each face is a quad, and its uv that quad's (a, b), in [0, 1]².
        std::vector<Shape> box{{BoxShape{{-1, -1, -6}, {1, 1, -4}, {}}, 0, "b"}};
        const auto b = World(scene_of(box), {TriangleTest::kWatertight, accel})
                           .intersect(Ray{{0.5f, -0.5f, 0}, {0, 0, -1}});
        REQUIRE(b);
        CHECK(b->normal == Vec3{0, 0, 1});
        // The +z face runs from the corner (−1, −1, −4) along x (u) and y (v), box_faces' order.
        CHECK(b->uv.x == Approx(0.75));
        CHECK(b->uv.y == Approx(0.25));
        // A plane's coordinates in its tangent basis, in scene units (y up: u along z, v along x).
        std::vector<Shape> plane{{PlaneShape{{0, 0, 0}, {0, 1, 0}}, 0, "p"}};
        const auto p =
            World(scene_of(plane), {TriangleTest::kWatertight, accel}).intersect(Ray{{2, 3, -7}, {0, -1, 0}});
        REQUIRE(p);
        CHECK(p->uv == Vec2d{-7, 2});
    }
}

// ---- Smooth meshes: shading normals and texture coordinates ----

namespace {

// One triangle of a mesh in the z = 0 plane (front side +z), with the given vertex normals and texture
// coordinates at its corners.
Scene smooth_triangle(const std::array<Vec3, 3>& normals) {
    MeshShape mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    mesh.normals = {glm::normalize(normals[0]), glm::normalize(normals[1]), glm::normalize(normals[2])};
    mesh.normal_corners = mesh.triangles;
    mesh.texture_coordinates = {{0.5f, 0}, {1, 0}, {0.5f, 1}};
    mesh.texture_corners = mesh.triangles;
    return scene_of({Shape{mesh, 0, "mesh"}});
}

}  // namespace

TEST_CASE("A smooth mesh's hit interpolates its vertex normals and texture coordinates with the barycentrics",
          "[shading_normal][ex:ch02.triangle_watertight]") {
    const Scene scene = smooth_triangle({Vec3{-1, 0, 2}, Vec3{1, 0, 2}, Vec3{0, 1, 2}});
    const World world(scene, world_options_for(EffectSet{Effect::kShadingNormals}));
    const Ray ray{{0.25f, 0.25f, 1}, {0, 0, -1}};  // b1 = b2 = 0.25, b0 = 0.5
    const auto hit = world.intersect(ray);
    REQUIRE(hit);
    const auto& n = scene.shapes[0].geometry;
    const MeshShape& mesh = std::get<MeshShape>(n);
    const Vec3 expected =
        glm::normalize(0.5f * mesh.normals[0] + 0.25f * mesh.normals[1] + 0.25f * mesh.normals[2]);
    CHECK(glm::length(hit->shading_normal - expected) < 1e-6f);
    CHECK(hit->normal == Vec3(0, 0, 1));
    CHECK(glm::length(hit->uv - Vec2d(0.625f, 0.25f)) < 1e-6);  // 0.5 (0.5, 0) + 0.25 (1, 0) + 0.25 (0.5, 1)
    // From behind, the geometric normal turns to the viewer, and the shading normal with it.
    const auto back = world.intersect(Ray{{0.25f, 0.25f, -1}, {0, 0, 1}});
    REQUIRE(back);
    CHECK(glm::length(back->shading_normal + expected) < 1e-6f);
    // Where the run does not simulate shading normals (chapters 02 and 03) the mesh is faceted, bit for bit.
    const World flat(scene);
    CHECK(flat.intersect(ray)->shading_normal == hit->normal);
}

TEST_CASE("A mesh without normals is faceted and its texture coordinates are the barycentrics (b1, b2)",
          "[shading_normal][ex:ch02.triangle_watertight]") {
    MeshShape mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    const World world(scene_of({Shape{mesh, 0, "mesh"}}), world_options_for(EffectSet::all()));
    const auto hit = world.intersect(Ray{{0.25f, 0.5f, 1}, {0, 0, -1}});
    REQUIRE(hit);
    CHECK(hit->shading_normal == hit->normal);
    CHECK(hit->uv == Vec2d(0.25f, 0.5f));
}

TEST_CASE(
    "The shading normal fix: flipped to the geometric side, bent above the viewer's horizon, else untouched",
    "[shading_normal]") {
    const Vec3 ng{0, 0, 1};
    // Already good: returned bit for bit.
    const Vec3 tilted = glm::normalize(Vec3{0.3f, 0, 1});
    const Vec3 wo = glm::normalize(Vec3{-0.2f, 0.1f, 1});
    CHECK(shading_normal(tilted, ng, wo, ShadingNormalFix::kBend) == tilted);
    // Vertex normals against the winding: flipped into the geometric hemisphere.
    CHECK(shading_normal(-tilted, ng, wo, ShadingNormalFix::kBend) == tilted);
    CHECK(shading_normal(tilted, ng, wo, ShadingNormalFix::kFlat) == ng);
    // A shading normal facing away from the viewer (the black fringe): without the fix wo is below its
    // horizon, with it wo is exactly kShadingHorizon above, the normal is unit and still on the geometric
    // side.
    const Vec3 away = glm::normalize(Vec3{0.8f, 0, 0.6f});
    const Vec3 from_left = glm::normalize(Vec3{-0.9f, 0, 0.3f});
    CHECK(glm::dot(shading_normal(away, ng, from_left, ShadingNormalFix::kNone), from_left) < 0);
    const Vec3 bent = shading_normal(away, ng, from_left, ShadingNormalFix::kBend);
    CHECK(glm::dot(bent, from_left) == Approx(kShadingHorizon).margin(1e-6));
    CHECK(glm::length(bent) == Approx(1).margin(1e-6));
    CHECK(glm::dot(bent, ng) > 0);
    // Grazing rays, 1e-6 to 1e-2 above the geometric surface, against normals tilted up to 80°: finite, unit,
    // wo above the shading horizon, on the geometric side.
    for (const Real height : {Real(1e-6), Real(1e-4), Real(1e-2)}) {
        for (const Real tilt_degrees : {Real(0), Real(20), Real(45), Real(80)}) {
            for (const Real azimuth : {Real(0), Real(90), Real(180), Real(270)}) {
                const Real t = radians(tilt_degrees), a = radians(azimuth);
                const Vec3 n{std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)};
                const Vec3 grazing = glm::normalize(Vec3{-1, 0, height});
                const Vec3 s = shading_normal(n, ng, grazing, ShadingNormalFix::kBend);
                INFO("height " << height << ", tilt " << tilt_degrees << ", azimuth " << azimuth);
                REQUIRE(is_finite(s));
                CHECK(glm::length(s) == Approx(1).margin(1e-5));
                CHECK(glm::dot(s, grazing) >= kShadingHorizon * (1 - 1e-3f));
                CHECK(glm::dot(s, ng) >= -1e-6f);
            }
        }
    }
    // The one case with no plane to bend in, ns = −wo (a tangent normal, wo grazing from the other side): the
    // geometric normal.
    CHECK(shading_normal(Vec3{1, 0, 0}, ng, glm::normalize(Vec3{-1, 0, 1e-7f}), ShadingNormalFix::kBend) ==
          ng);
}

TEST_CASE("Every camera hit on the smooth torus, silhouettes included, sees wo above the shading horizon",
          "[shading_normal][ex:ch02.slab_test][ex:ch02.slab_widening][ex:ch02.wide_bvh_traversal]") {
    MeshShape torus = make_torus(1, Real(0.4), 24, 12);
    const Scene scene = scene_of({Shape{torus, 0, "torus"}});
    const World bend(scene, world_options_for(EffectSet{Effect::kShadingNormals}));
    const World raw(scene, world_options_for(EffectSet{Effect::kShadingNormals}, ShadingNormalFix::kNone));
    int hits = 0, below_raw = 0;
    for (int i = 0; i < 200; ++i) {
        for (int j = 0; j < 200; ++j) {
            const Vec3 origin{-1.6f + 3.2f * Real(i) / 199, -0.6f + 1.2f * Real(j) / 199, 3};
            const Ray ray{origin, glm::normalize(Vec3{0, -0.35f, -1})};
            const auto h = bend.intersect(ray);
            if (!h) continue;
            ++hits;
            below_raw += glm::dot(raw.intersect(ray)->shading_normal, -ray.direction) <= 0;
            REQUIRE(glm::dot(h->shading_normal, -ray.direction) >= kShadingHorizon * (1 - 1e-3f));
            REQUIRE(glm::dot(h->shading_normal, h->normal) >= -1e-6f);
        }
    }
    CHECK(hits > 5000);  // a quarter of the rays or so hit the torus
    // The coarse torus has hits whose raw normal faces away (black with every BRDF): the fix has work to do.
    // The lesson's table (chapter 04, "Shading normals") quotes this line.
    WARN("smooth torus, 24 x 12: " << hits << " camera hits, " << below_raw << " ("
                                   << 100.0 * below_raw / hits
                                   << " %) with the raw normal facing away from the viewer, 0 with the fix");
    CHECK(below_raw > 0);
}

namespace fs = std::filesystem;

TEST_CASE("The torus written as OBJ and as PLY loads to the same corners: positions, normals, coordinates",
          "[shading_normal][mesh]") {
    const fs::path folder = fs::temp_directory_path() / ("rt_torus_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    const MeshShape torus = make_torus(1, Real(0.4), 8, 5);
    write_obj(torus, folder / "torus.obj");
    write_ply(torus, folder / "torus.ply");
    for (const char* name : {"torus.obj", "torus.ply"}) {
        std::ofstream(folder / "scene.json")
            << R"({"camera": {"from": [0, 0, 5], "at": [0, 0, 0]}, "materials": {"m": {"type": "diffuse"}},
                  "shapes": [{"type": "mesh", "file": ")"
            << name << R"(", "material": "m",
                              "transform": {"scale": [2, 1, 1]}}]})";
        const Scene scene = load_scene(folder / "scene.json");
        const MeshShape& m = std::get<MeshShape>(scene.shapes[0].geometry);
        INFO(name);
        REQUIRE(m.triangles.size() == torus.triangles.size());
        for (std::size_t t = 0; t < m.triangles.size(); ++t) {
            for (std::size_t k = 0; k < 3; ++k) {
                const Vec3 p = torus.positions[torus.triangles[t][k]];
                CHECK(glm::length(m.positions[m.triangles[t][k]] - Vec3{2 * p.x, p.y, p.z}) < 1e-6f);
                // A normal follows the inverse transpose: (nx / 2, ny, nz), normalised.
                const Vec3 n = torus.normals[torus.normal_corners[t][k]];
                CHECK(glm::length(m.normals[m.normal_corners[t][k]] -
                                  glm::normalize(Vec3{n.x / 2, n.y, n.z})) < 1e-6f);
                CHECK(m.texture_coordinates[m.texture_corners[t][k]] ==
                      torus.texture_coordinates[torus.texture_corners[t][k]]);
            }
        }
    }
    fs::remove_all(folder);
}
