#include "leak_probe.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "world.hpp"

namespace rt {
namespace {

std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_uses(const MeshShape& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const auto& t : mesh.triangles) {
        for (int i = 0; i < 3; ++i) ++uses[std::minmax(t[std::size_t(i)], t[std::size_t((i + 1) % 3)])];
    }
    return uses;
}

}  // namespace

bool is_closed(const MeshShape& mesh) {
    for (const auto& [edge, count] : edge_uses(mesh)) {
        if (count != 2) return false;
    }
    return !mesh.triangles.empty();
}

std::vector<Ray> leak_probe_rays(const MeshShape& mesh) {
    Vec3d sum{0};
    for (const Vec3& p : mesh.positions) sum += Vec3d(p);
    const Vec3 centroid{sum / double(mesh.positions.size())};
    std::vector<Ray> rays;
    auto aim = [&](const Vec3& target) { rays.push_back(Ray{centroid, glm::normalize(target - centroid)}); };
    for (const Vec3& p : mesh.positions) aim(p);
    for (const auto& [edge, count] : edge_uses(mesh)) {
        const Vec3 a = mesh.positions[edge.first], b = mesh.positions[edge.second];
        for (Real s : {Real(0.25), Real(0.5), Real(0.75)}) aim(a + s * (b - a));
    }
    return rays;
}

LeakProbe probe_leaks(const MeshShape& mesh, TriangleTest test) {
    Scene scene;
    scene.materials.push_back(Material{});
    scene.shapes.push_back(Shape{mesh, 0, "probe"});
    const World world(scene, {test, Acceleration::kBvh});
    LeakProbe probe;
    for (const Ray& ray : leak_probe_rays(mesh)) {
        ++probe.rays;
        if (!world.nearest(ray)) ++probe.escaped;
    }
    return probe;
}

}  // namespace rt
