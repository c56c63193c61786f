// Chapter 02: intersection. Plain cases first, then the hard cases ([stability]).
#include <catch2/catch.hpp>

#include <cmath>

#include "aabb.hpp"
#include "world.hpp"

using namespace rt;

namespace {

Scene scene_of(std::vector<Shape> shapes) {
    Scene scene;
    scene.materials.push_back(Material{});
    scene.shapes = std::move(shapes);
    return scene;
}

}  // namespace

TEST_CASE("A ray hits the near side of a sphere in front of it", "[sphere]") {
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    const auto t = intersect_sphere(ray, Sphere{{0, 0, -5}, 1}, kInfinity);
    REQUIRE(t);
    CHECK(*t == Approx(4));
    CHECK_FALSE(intersect_sphere(ray, Sphere{{0, 3, -5}, 1}, kInfinity));
    CHECK_FALSE(intersect_sphere(ray, Sphere{{0, 0, -5}, 1}, 3));
}

TEST_CASE("The world returns the nearest of several shapes with a normal facing the ray", "[world]") {
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
        CHECK(world.occluded(Ray{{0, 0, 0}, {0, 0, -1}}, 6));
        CHECK_FALSE(world.occluded(Ray{{0, 0, 0}, {0, 0, -1}}, 4));
        const auto far = world.intersect(Ray{{5, 0, 0}, {0, 0, -1}});
        REQUIRE(far);
        CHECK(far->primitive == 2);
        CHECK(far->t == Approx(20));
    }
}
