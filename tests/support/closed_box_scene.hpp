// A furnace with an exact answer, for every chapter that traces paths: six walls of emission 0.5 and albedo
// 0.5 around the camera, so every point sees radiance L = Le + ρ L = 1, at every bounce.
#pragma once

#include <utility>

#include "rt/core/scene.hpp"

namespace rt::test {

inline Scene closed_box_scene() {
    Scene scene;
    scene.file = "closed box";
    scene.camera = CameraDesc{{0.1f, 0.2f, 0.3f}, {0.1f, 0.2f, -1}, {0, 1, 0}, 70};
    Material wall;
    wall.name = "glowing wall";
    wall.albedo = Color(0.5f);
    wall.emission = Color(0.5f);
    scene.materials.push_back(wall);
    // The six faces of [−1, 1]³, each with u × v pointing in.
    const Vec3 a{-1, -1, -1};
    const std::pair<Vec3, Vec3> x_face{{0, 2, 0}, {0, 0, 2}}, y_face{{0, 0, 2}, {2, 0, 0}},
        z_face{{2, 0, 0}, {0, 2, 0}};
    scene.shapes.push_back(Shape{QuadShape{a, x_face.first, x_face.second}, 0, "x = -1"});
    scene.shapes.push_back(Shape{QuadShape{{1, -1, -1}, x_face.second, x_face.first}, 0, "x = 1"});
    scene.shapes.push_back(Shape{QuadShape{a, y_face.first, y_face.second}, 0, "y = -1"});
    scene.shapes.push_back(Shape{QuadShape{{-1, 1, -1}, y_face.second, y_face.first}, 0, "y = 1"});
    scene.shapes.push_back(Shape{QuadShape{a, z_face.first, z_face.second}, 0, "z = -1"});
    scene.shapes.push_back(Shape{QuadShape{{-1, -1, 1}, z_face.second, z_face.first}, 0, "z = 1"});
    return scene;
}

}  // namespace rt::test
