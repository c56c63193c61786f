// A strict reader of Wavefront OBJ text, for the meshes of a scene. The course reads OBJ itself rather than
// through tinyobjloader, which reads "v nan 0 0", "v abc def ghi" and "v -1 0" as zeros or partial vertices
// and the face indices "3abc", "3.7" and 2^32 + 3 as vertex 3, and cannot be asked not to.
//
// Every number is read as the scene file's numbers are: wholly consumed, finite, within the limits; an error
// names the line and column. What it reads: v (x y z, then an optional w, or r g b), vt, vn, f (corners v,
// v/vt, v//vn, v/vt/vn; negative indices count back from the last vertex so far), and o, g, s, usemtl,
// mtllib, l, p, which are skipped (no other file is ever opened). Comments start with #; a UTF-8 byte order
// mark and CRLF line ends are allowed. A face gives texture coordinates (normals) at all its corners or at
// none, and so does every face of the file as its first one; a zero normal is refused.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "rt/core/math.hpp"

namespace rt {

// A face's corners: positions always; texture coordinates and normals either at every corner or at none
// (a face that gives them at some corners only is refused).
struct ObjFace {
    std::vector<std::uint32_t> vertices;  // indices into ObjMesh::positions, at least 3
    std::vector<std::uint32_t> texture_coordinates;  // into ObjMesh::texture_coordinates, or empty
    std::vector<std::uint32_t> normals;              // into ObjMesh::normals, or empty
    std::size_t line;                                // where it is in the file, for messages
};

struct ObjMesh {
    std::vector<Vec3> positions;
    std::vector<Vec2> texture_coordinates;  // vt u [v [w]]: (u, v), v = 0 when absent, w dropped
    std::vector<Vec3> normals;              // vn x y z, as written (not zero; normalised by the loader)
    std::vector<ObjFace> faces;
};

// Throws InputError "line L, column C: what was expected, got what was found" (L and C from 1; the caller puts
// the file's name before it). Coordinates beyond `largest_coordinate` in magnitude are refused.
ObjMesh parse_obj(std::string_view text, double largest_coordinate);

}  // namespace rt
