#include "furnace.hpp"

#include <cmath>

#include "04_direct_lighting/brdf.hpp"
#include "04_direct_lighting/material_table.hpp"

namespace rt {
namespace {

Vec3d to_double(const Color& c) {
    return {double(c.r), double(c.g), double(c.b)};
}

// Directions spread evenly over the sphere (a Fibonacci spiral): z = 1 − (2i + 1) / n, φ = i · golden angle.
Vec3 spiral_direction(int i, int n) {
    const double z = 1 - (2 * i + 1) / double(n);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const double phi = i * 2.399963229728653;  // π (3 − √5)
    return {Real(r * std::cos(phi)), Real(r * std::sin(phi)), Real(z)};
}

}  // namespace

Vec3d furnace_radiance(const Furnace& furnace) {
    return to_double(furnace.emission) / (1.0 - to_double(furnace.albedo));
}

Vec3d furnace_radiance_truncated(const Furnace& furnace, int bounces) {
    const Vec3d rho = to_double(furnace.albedo);
    const Vec3d power = glm::pow(rho, Vec3d(double(bounces) + 1));
    return to_double(furnace.emission) * (1.0 - power) / (1.0 - rho);
}

Scene make_furnace_scene(const Furnace& furnace, const Vec3& eye, const Vec3& at) {
    Scene scene;
    scene.file = "furnace";
    scene.camera = CameraDesc{eye, at, {0, 1, 0}, 90};
    scene.image = ImageDesc{32, 32, 4};
    Material wall;
    wall.name = "wall";
    wall.albedo = furnace.albedo;
    wall.emission = furnace.emission;
    scene.materials.push_back(wall);
    // (origin, u, v) with u × v pointing into the cube.
    const Vec3 faces[6][3] = {
        {{-1, -1, -1}, {2, 0, 0}, {0, 2, 0}},  // z = −1
        {{-1, -1, 1}, {0, 2, 0}, {2, 0, 0}},   // z = +1
        {{-1, -1, -1}, {0, 2, 0}, {0, 0, 2}},  // x = −1
        {{1, -1, -1}, {0, 0, 2}, {0, 2, 0}},   // x = +1
        {{-1, -1, -1}, {0, 0, 2}, {2, 0, 0}},  // y = −1
        {{-1, 1, -1}, {2, 0, 0}, {0, 0, 2}},   // y = +1
    };
    for (int i = 0; i < 6; ++i) {
        scene.shapes.push_back(
            Shape{QuadShape{faces[i][0], faces[i][1], faces[i][2]}, 0, "shapes[" + std::to_string(i) + "]"});
    }
    return scene;
}

std::optional<Furnace> find_furnace(const Scene& scene, const World& world) {
    if (scene.shapes.empty() || scene.has_delta_lights() || scene.environment) return std::nullopt;
    const int material = scene.shapes.front().material;
    for (const Shape& s : scene.shapes) {
        if (s.material != material) return std::nullopt;
    }
    const Material& m = scene.materials[std::size_t(material)];
    // Diffuse: what the material table makes a Lambert BRDF of when every effect is simulated.
    const MaterialTable materials(scene, EffectSet::all());
    const auto* lambert = dynamic_cast<const LambertBrdf*>(&materials.bsdf(material));
    if (!lambert || !m.emissive()) return std::nullopt;
    for (int c = 0; c < 3; ++c) {
        if (!(lambert->albedo[c] >= 0 && lambert->albedo[c] < 1)) return std::nullopt;
    }
    constexpr int kProbes = 1000;
    for (int i = 0; i < kProbes; ++i) {
        const auto hit = world.intersect(Ray{scene.camera.from, spiral_direction(i, kProbes)});
        if (!hit || !hit->front_face) return std::nullopt;
    }
    return Furnace{lambert->albedo, m.emission};
}

Image furnace_image(const Furnace& furnace, int width, int height) {
    Image image(width, height);
    const Vec3d L = furnace_radiance(furnace);
    for (Color& c : image.pixels()) c = Color(Real(L.x), Real(L.y), Real(L.z));
    return image;
}

}  // namespace rt
