// Does a closed mesh leak? From a point inside a closed, star-shaped mesh every ray must hit it. The probe
// aims rays from the centroid of its vertices exactly at every vertex and at points on every edge — where
// two triangles meet and rounding decides which one is hit, or neither.
#pragma once

#include <cstdint>
#include <vector>

#include "rt/core/ray.hpp"
#include "rt/core/scene.hpp"
#include "triangle.hpp"

namespace rt {

// Whether every edge of the mesh is shared by exactly two triangles (a closed surface).
bool is_closed(const MeshShape& mesh);

struct LeakProbe {
    std::uint64_t rays = 0;
    std::uint64_t escaped = 0;  // rays from inside that hit nothing
};

// The probe's rays: from the vertex centroid to every vertex and to the points at 1/4, 1/2 and 3/4 of every
// edge.
std::vector<Ray> leak_probe_rays(const MeshShape& mesh);

// The probe's rays, each intersected with the mesh alone (through a BVH) by the given triangle test.
LeakProbe probe_leaks(const MeshShape& mesh, TriangleTest test);

}  // namespace rt
