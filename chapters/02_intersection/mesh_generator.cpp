#include "mesh_generator.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdio>
#include <fstream>
#include <map>
#include <utility>

#include "rt/core/errors.hpp"
#include "rt/core/random.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/staged_file.hpp"

namespace rt {

MeshShape make_icosphere(int subdivisions) {
    MeshShape mesh;
    const Real g = (1 + std::sqrt(Real(5))) / 2;  // the golden ratio: vertices (0, ±1, ±g) and their cycles
    for (const Vec3& p :
         {Vec3{-1, g, 0}, Vec3{1, g, 0}, Vec3{-1, -g, 0}, Vec3{1, -g, 0}, Vec3{0, -1, g}, Vec3{0, 1, g},
          Vec3{0, -1, -g}, Vec3{0, 1, -g}, Vec3{g, 0, -1}, Vec3{g, 0, 1}, Vec3{-g, 0, -1}, Vec3{-g, 0, 1}}) {
        mesh.positions.push_back(glm::normalize(p));
    }
    mesh.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < subdivisions; ++level) {
        // Each edge gets one midpoint vertex, shared by the two triangles on either side of it.
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto [it, inserted] = midpoints.try_emplace(key, std::uint32_t(mesh.positions.size()));
            if (inserted) mesh.positions.push_back(glm::normalize(mesh.positions[a] + mesh.positions[b]));
            return it->second;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        finer.reserve(mesh.triangles.size() * 4);
        for (const auto& t : mesh.triangles) {
            const std::uint32_t ab = midpoint(t[0], t[1]);
            const std::uint32_t bc = midpoint(t[1], t[2]);
            const std::uint32_t ca = midpoint(t[2], t[0]);
            finer.push_back({t[0], ab, ca});
            finer.push_back({t[1], bc, ab});
            finer.push_back({t[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        mesh.triangles = std::move(finer);
    }
    return mesh;
}

MeshShape make_uv_sphere(int segments, int rings) {
    MeshShape mesh;
    const auto s = std::uint32_t(segments);
    mesh.positions.push_back({0, 1, 0});  // north pole: vertex 0
    for (int r = 1; r < rings; ++r) {
        const Real theta = kPi * Real(r) / Real(rings);
        for (int k = 0; k < segments; ++k) {
            const Real phi = 2 * kPi * Real(k) / Real(segments);
            mesh.positions.push_back(
                {std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)});
        }
    }
    const auto south = std::uint32_t(mesh.positions.size());
    mesh.positions.push_back({0, -1, 0});
    auto at = [&](int ring, std::uint32_t k) { return 1 + std::uint32_t(ring - 1) * s + k % s; };
    for (std::uint32_t k = 0; k < s; ++k) {
        mesh.triangles.push_back({0, at(1, k), at(1, k + 1)});
        for (int r = 1; r + 1 < rings; ++r) {
            mesh.triangles.push_back({at(r, k), at(r + 1, k), at(r + 1, k + 1)});
            mesh.triangles.push_back({at(r, k), at(r + 1, k + 1), at(r, k + 1)});
        }
        mesh.triangles.push_back({at(rings - 1, k), south, at(rings - 1, k + 1)});
    }
    return mesh;
}

MeshShape make_torus(Real major, Real minor, int segments, int rings) {
    MeshShape mesh;
    const auto s = std::uint32_t(segments), r = std::uint32_t(rings);
    for (std::uint32_t i = 0; i < s; ++i) {
        const Real phi = 2 * kPi * Real(i) / Real(s);
        const Vec3 out{std::cos(phi), 0, -std::sin(phi)};  // from the y axis to the tube's centre
        for (std::uint32_t j = 0; j < r; ++j) {
            const Real theta = 2 * kPi * Real(j) / Real(r);
            const Vec3 n = std::cos(theta) * out + std::sin(theta) * Vec3{0, 1, 0};
            mesh.positions.push_back(major * out + minor * n);
            mesh.normals.push_back(n);
        }
    }
    // The texture coordinates have one more column and row than the positions: u = 1 and v = 1 close the
    // seam.
    for (std::uint32_t i = 0; i <= s; ++i) {
        for (std::uint32_t j = 0; j <= r; ++j)
            mesh.texture_coordinates.push_back({Real(i) / Real(s), Real(j) / Real(r)});
    }
    auto at = [&](std::uint32_t i, std::uint32_t j) { return (i % s) * r + j % r; };
    auto uv_at = [&](std::uint32_t i, std::uint32_t j) { return i * (r + 1) + j; };
    for (std::uint32_t i = 0; i < s; ++i) {
        for (std::uint32_t j = 0; j < r; ++j) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            mesh.texture_corners.push_back({uv_at(i, j), uv_at(i + 1, j), uv_at(i + 1, j + 1)});
            mesh.texture_corners.push_back({uv_at(i, j), uv_at(i + 1, j + 1), uv_at(i, j + 1)});
        }
    }
    mesh.normal_corners = mesh.triangles;
    return mesh;
}

void jitter_radii(MeshShape& mesh, Real amount, std::uint64_t seed) {
    Pcg32 rng(seed, 0);
    for (Vec3& p : mesh.positions) p *= 1 + amount * (2 * rng.next_real() - 1);
}

void write_obj(const MeshShape& mesh, const std::filesystem::path& path) {
    // Written under a staging name of this process (never `path` + ".tmp", which may be someone's file),
    // removed if anything fails, renamed into place when whole.
    check_writable(path);
    StagedFile obj(path);
    std::FILE* out = obj.file();
    std::fputs("# generated by the ray tracing course, chapter 02 (mesh_generator.cpp)\n", out);
    for (const Vec3& p : mesh.positions) {
        std::fprintf(out, "v %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
    }
    for (const Vec2& t : mesh.texture_coordinates)
        std::fprintf(out, "vt %.9g %.9g\n", double(t.x), double(t.y));
    for (const Vec3& n : mesh.normals) {
        std::fprintf(out, "vn %.9g %.9g %.9g\n", double(n.x), double(n.y), double(n.z));
    }
    const bool textured = !mesh.texture_corners.empty();
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        std::fputs("f", out);
        for (std::size_t k = 0; k < 3; ++k) {
            std::fprintf(out, " %u", mesh.triangles[i][k] + 1);
            if (textured) std::fprintf(out, "/%u", mesh.texture_corners[i][k] + 1);
            if (mesh.smooth()) std::fprintf(out, textured ? "/%u" : "//%u", mesh.normal_corners[i][k] + 1);
        }
        std::fputs("\n", out);
    }
    obj.commit();
}

namespace {

void put_le(std::FILE* out, std::uint32_t bits) {
    const unsigned char bytes[4] = {(unsigned char)(bits), (unsigned char)(bits >> 8),
                                    (unsigned char)(bits >> 16), (unsigned char)(bits >> 24)};
    std::fwrite(bytes, 1, 4, out);
}

}  // namespace

void write_ply(const MeshShape& mesh, const std::filesystem::path& path) {
    check_writable(path);
    StagedFile ply(path);
    std::FILE* out = ply.file();
    const bool textured = !mesh.texture_corners.empty();
    // PLY's vertices carry their attributes: one per distinct (position, normal, texture coordinate) corner.
    std::map<std::array<std::uint32_t, 3>, std::uint32_t> vertex_of;
    std::vector<std::array<std::uint32_t, 3>> vertices, faces;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        std::array<std::uint32_t, 3> face{};
        for (std::size_t k = 0; k < 3; ++k) {
            const std::array<std::uint32_t, 3> corner{mesh.triangles[i][k],
                                                      mesh.smooth() ? mesh.normal_corners[i][k] : 0,
                                                      textured ? mesh.texture_corners[i][k] : 0};
            const auto [it, inserted] = vertex_of.try_emplace(corner, std::uint32_t(vertices.size()));
            if (inserted) vertices.push_back(corner);
            face[k] = it->second;
        }
        faces.push_back(face);
    }
    std::fprintf(
        out,
        "ply\nformat binary_little_endian 1.0\ncomment generated by the ray tracing course, chapter 02 "
        "(mesh_generator.cpp)\nelement vertex %zu\nproperty float x\nproperty float y\nproperty float z\n",
        vertices.size());
    if (mesh.smooth()) std::fputs("property float nx\nproperty float ny\nproperty float nz\n", out);
    if (textured) std::fputs("property float u\nproperty float v\n", out);
    std::fprintf(out, "element face %zu\nproperty list uchar uint vertex_indices\nend_header\n",
                 faces.size());
    auto put_float = [&](Real x) { put_le(out, std::bit_cast<std::uint32_t>(float(x))); };
    for (const auto& [p, n, t] : vertices) {
        for (int a = 0; a < 3; ++a) put_float(mesh.positions[p][a]);
        for (int a = 0; a < 3 && mesh.smooth(); ++a) put_float(mesh.normals[n][a]);
        for (int a = 0; a < 2 && textured; ++a) put_float(mesh.texture_coordinates[t][a]);
    }
    for (const auto& face : faces) {
        std::fputc(3, out);
        for (std::uint32_t v : face) put_le(out, v);
    }
    ply.commit();
}

void write_default_mesh(const std::filesystem::path& path) {
    MeshShape mesh = make_icosphere(3);
    jitter_radii(mesh, Real(0.05), 2);
    write_obj(mesh, path);
    std::printf("wrote %s: %zu vertices, %zu triangles\n", path.string().c_str(), mesh.positions.size(),
                mesh.triangles.size());
}

void write_smooth_torus(const std::filesystem::path& path) {
    const MeshShape mesh = make_torus(1, Real(0.4), 24, 12);
    if (path.extension() == ".ply") {
        write_ply(mesh, path);
    } else {
        write_obj(mesh, path);
    }
    std::printf("wrote %s: %zu vertices with normals and texture coordinates, %zu triangles\n",
                path.string().c_str(), mesh.positions.size(), mesh.triangles.size());
}

}  // namespace rt
