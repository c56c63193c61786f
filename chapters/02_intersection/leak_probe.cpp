#include "leak_probe.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "world.hpp"

namespace rt {
namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;  // (smaller index, larger index)

// Every triangle's three edges, sorted, so that the uses of one edge sit side by side: 8 bytes per use, where
// a map of edges would allocate a node per edge (72 MB for a million triangles).
std::vector<Edge> sorted_edges(const MeshShape& mesh) {
    std::vector<Edge> edges;
    edges.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        for (std::size_t i = 0; i < 3; ++i) edges.push_back(std::minmax(t[i], t[(i + 1) % 3]));
    }
    std::sort(edges.begin(), edges.end());
    return edges;
}

}  // namespace

bool is_closed(const MeshShape& mesh) {
    const std::vector<Edge> edges = sorted_edges(mesh);
    for (std::size_t i = 0; i < edges.size(); i += 2) {  // each edge used exactly twice
        const bool twice = i + 1 < edges.size() && edges[i + 1] == edges[i];
        if (!twice || (i + 2 < edges.size() && edges[i + 2] == edges[i])) return false;
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
    const std::vector<Edge> edges = sorted_edges(mesh);
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (i > 0 && edges[i] == edges[i - 1]) continue;  // each edge once
        const Vec3 a = mesh.positions[edges[i].first], b = mesh.positions[edges[i].second];
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
