// A strict reader of PLY (the Stanford polygon format), ASCII and binary (little- and big-endian), for the
// meshes of a scene; the course reads it itself for the reasons it reads OBJ itself (obj_parser.hpp).
//
// What it reads: the header (ply, format, comment, obj_info, element, property, end_header; types char,
// uchar, short, ushort, int, uint, float, double and their int8 ... float64 names), then every element's
// data, exactly as many as the header counts, and nothing after. The "vertex" element gives x y z, optionally
// nx ny nz (all three or none) and texture coordinates (u v, s t, texture_u texture_v or texture_s
// texture_t); the "face" element a list "vertex_indices" (or "vertex_index") of 3 or more vertices. Every
// other property and element is read and skipped. Numbers are finite and within the limits, indices whole and
// in range, a normal not zero. An error names its place: "line L: ..." in the header and in ASCII data,
// "element face 37 (byte offset B): ..." in binary data (elements and offsets from 0).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "rt/core/math.hpp"

namespace rt {

struct PlyMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;              // one per position, or empty
    std::vector<Vec2> texture_coordinates;  // one per position, or empty
    // Every face's indices into positions (at least 3), one face after another; face f is corners[face_starts[f]]
    // up to corners[face_starts[f + 1]]. Flat: a vector per face would cost an allocation per face.
    std::vector<std::uint32_t> corners;
    std::vector<std::size_t> face_starts{0};

    std::size_t face_count() const { return face_starts.size() - 1; }
    std::span<const std::uint32_t> face(std::size_t f) const {
        return {corners.data() + face_starts[f], corners.data() + face_starts[f + 1]};
    }
};

// Throws InputError with the place (the caller puts the file's name before it). Coordinates beyond
// `largest_coordinate` in magnitude are refused.
PlyMesh parse_ply(std::string_view bytes, double largest_coordinate);

}  // namespace rt
