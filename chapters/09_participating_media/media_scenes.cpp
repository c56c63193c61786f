#include "media_scenes.hpp"

namespace rt {

Scene medium_sphere_scene(const MediumDesc& medium, Real ior, Real sky) {
    Scene scene;
    scene.file = "medium sphere";
    scene.camera = {{0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 30};
    Material m;
    m.name = "medium";
    m.type = "dielectric";
    m.roughness = 0;
    m.ior = ior;
    m.medium = medium;
    scene.materials.push_back(m);
    scene.shapes.push_back({SphereShape{{0, 0, 0}, 1}, 0, "shapes[0]"});
    scene.environment = EnvironmentLight{Color(sky)};
    return scene;
}

Scene medium_slab_scene(const MediumDesc& medium, Real thickness) {
    Scene scene;
    scene.file = "medium slab";
    scene.camera = {{0, thickness + 1, 0}, {0, 0, 0}, {0, 0, 1}, 1};
    Material slab;
    slab.name = "slab";
    slab.type = "dielectric";
    slab.roughness = 0;
    slab.ior = 1;
    slab.medium = medium;
    Material black;
    black.name = "black";
    black.albedo = Color(0);
    scene.materials = {slab, black};
    const Real w = 1e4;
    scene.shapes.push_back({BoxShape{{-w, 0, -w}, {w, thickness, w}, {}}, 0, "shapes[0]"});
    scene.shapes.push_back({PlaneShape{{0, -2, 0}, {0, 1, 0}}, 1, "shapes[1]"});
    scene.environment = EnvironmentLight{Color(1)};
    return scene;
}

}  // namespace rt
