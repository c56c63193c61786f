// Meshes the course generates itself: closed spheres and a smooth torus made of triangles with shared
// vertices, and OBJ and PLY writers, so every mesh in assets/meshes can be regenerated from this code.
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

// A torus about the y axis, of radius `major` to the tube's centre and `minor` for the tube: `segments`
// around y, `rings` around the tube, 2 · segments · rings triangles, counter-clockwise seen from outside,
// closed. It has the exact surface's unit normals at its vertices and texture coordinates (u, v) = (around y,
// around the tube) in [0, 1]², with a seam of its own (texture_corners) where u and v wrap.
MeshShape make_torus(Real major, Real minor, int segments, int rings);

// Moves each vertex along its direction from the origin by a factor in [1 − amount, 1 + amount], with a
// fixed seed: still closed, still star-shaped around the origin, no longer a convex polyhedron.
void jitter_radii(MeshShape& mesh, Real amount, std::uint64_t seed);

// Writes "v x y z", then any "vt u v" and "vn x y z", and "f i j k" lines (1-based indices, "i/t/n" with
// texture coordinates and normals) under a staging name renamed into place when whole (staged_file.hpp).
// Throws InputError when `path` cannot be written, std::runtime_error when a write fails.
void write_obj(const MeshShape& mesh, const std::filesystem::path& path);

// Writes a binary little-endian PLY: each distinct corner (position, normal, texture coordinate) one vertex
// with x y z [nx ny nz] [u v] as floats, each triangle a face of 3 uint indices. Throws as write_obj does.
void write_ply(const MeshShape& mesh, const std::filesystem::path& path);

// Writes the smooth torus of chapter 04's lesson (radii 1 and 0.4, 24 × 12) as OBJ, or PLY when `path` ends
// in .ply, and prints what it wrote.
void write_smooth_torus(const std::filesystem::path& path);

// Writes chapter 02's default mesh (the icosphere of 3 subdivisions, radii jittered by 5%, seed 2) as OBJ and
// prints what it wrote.
void write_default_mesh(const std::filesystem::path& path);

}  // namespace rt
