// Meshes the course generates itself: closed spheres made of triangles with shared vertices, and an OBJ
// writer, so every mesh in assets/meshes can be regenerated from this code.
#pragma once

#include <cstdint>
#include <filesystem>

#include "rt/core/scene.hpp"

namespace rt {

// The icosahedron subdivided `subdivisions` times, every vertex pushed onto the unit sphere:
// 20 · 4^subdivisions triangles, counter-clockwise seen from outside, each edge shared by two triangles.
MeshShape make_icosphere(int subdivisions);

// A latitude–longitude sphere: `segments` around, `rings` from pole to pole; 2 · segments · (rings − 1)
// triangles (a fan at each pole), counter-clockwise seen from outside, closed.
MeshShape make_uv_sphere(int segments, int rings);

// Moves each vertex along its direction from the origin by a factor in [1 − amount, 1 + amount], with a
// fixed seed: still closed, still star-shaped around the origin, no longer a convex polyhedron.
void jitter_radii(MeshShape& mesh, Real amount, std::uint64_t seed);

// Writes "v x y z" and "f i j k" lines (1-based indices) under a staging name renamed into place when whole
// (staged_file.hpp). Throws InputError when `path` cannot be written, std::runtime_error when a write fails.
void write_obj(const MeshShape& mesh, const std::filesystem::path& path);

// Writes chapter 02's default mesh (the icosphere of 3 subdivisions, radii jittered by 5%, seed 2) as OBJ and
// prints what it wrote.
void write_default_mesh(const std::filesystem::path& path);

}  // namespace rt
