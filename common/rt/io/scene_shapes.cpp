#include "rt/io/scene_shapes.hpp"

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <span>
#include <utility>

#include "rt/io/input_file.hpp"
#include "rt/io/obj_parser.hpp"
#include "rt/io/ply_parser.hpp"

namespace rt::scene_reading {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kShapeTypes[] = {"sphere", "quad", "triangle", "plane", "box", "mesh"};
constexpr std::string_view kTransformKeys[] = {"scale", "rotate_x", "rotate_y", "rotate_z", "translate"};
constexpr std::string_view kMeshTransformKeys[] = {"scale",     "rotate_x", "rotate_y",
                                                   "rotate_z",  "translate", "matrix"};

// A mesh's "matrix": three rows [a, b, c, d] of the affine map x' = a x + b y + c z + d, invertible.
glm::dmat4 read_matrix(const Node& node) {
    if (node.array_size() != 3) node.fail("must be 3 rows of 4 numbers, got " + std::to_string(node.array_size()));
    glm::dmat4 m(1.0);
    for (std::size_t row = 0; row < 3; ++row) {
        const Node r = node.element(row);
        if (r.array_size() != 4) r.fail("must be a row of 4 numbers, got " + std::to_string(r.array_size()));
        for (std::size_t col = 0; col < 4; ++col) m[int(col)][int(row)] = r.element(col).number();
    }
    if (!(std::abs(glm::determinant(glm::dmat3(m))) > 1e-30)) node.fail("must be invertible, got determinant 0");
    return m;
}

Transform read_transform(const Node& node, bool mesh = false) {
    if (mesh) {
        node.expect_object(kMeshTransformKeys);
    } else {
        node.expect_object(kTransformKeys);
    }
    Transform t;
    if (node.has("matrix")) {
        if (node.json().size() != 1) node["matrix"].fail("must be the transform's only key");
        t.matrix = read_matrix(node["matrix"]);
        return t;
    }
    if (node.has("scale")) {
        const Node scale = node["scale"];
        t.scale = scale.json().is_array() ? scale.vec3() : Vec3(scale.real());
        for (int i = 0; i < 3; ++i) {
            if (t.scale[i] == 0) scale.fail("must not be zero (it would flatten the shape)");
        }
    }
    if (node.has("rotate_x")) t.rotate_degrees.x = node["rotate_x"].real();
    if (node.has("rotate_y")) t.rotate_degrees.y = node["rotate_y"].real();
    if (node.has("rotate_z")) t.rotate_degrees.z = node["rotate_z"].real();
    if (node.has("translate")) t.translate = node["translate"].vec3();
    return t;
}

// |a × b| ≤ 1e-7 |a| |b| (in double), or a × b too short for float to normalise: the parallelogram (or
// triangle) of a and b has no area worth rendering, and its normal would be NaN.
bool zero_area(const Vec3& a, const Vec3& b) {
    const Vec3d da(a), db(b);
    return glm::length(glm::cross(da, db)) <= 1e-7 * glm::length(da) * glm::length(db) ||
           !normalisable(glm::cross(a, b));
}

// A point after a transform (scale · rotation + translation) must stay inside the limits of a scene file.
void check_within_limits(const Node& node, const std::string& what, const Vec3& p) {
    for (int i = 0; i < 3; ++i) {
        if (!(std::abs(double(p[i])) <= kLargestNumber)) {
            node.fail("moves " + what + " to " + show(p) + ", beyond the limit of " + show(kLargestNumber));
        }
    }
}

// The triangles a polygon (a, b, c, ...) is split into: the fan (a, b, c), (a, c, d), ...
template <class Corners>
void add_fan(std::span<const std::uint32_t> polygon, Corners& triangles) {
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
        triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
}

// A mesh file's polygons as triangles: an OBJ file (obj_parser.hpp) with its own indices for texture
// coordinates and normals, or a PLY file (ply_parser.hpp) whose vertices carry them. The normals are not yet
// transformed.
void read_obj_into(MeshShape& mesh, std::string_view text) {
    ObjMesh parsed = parse_obj(text, kLargestNumber);
    mesh.positions = std::move(parsed.positions);
    mesh.normals = std::move(parsed.normals);
    mesh.texture_coordinates = std::move(parsed.texture_coordinates);
    for (const ObjFace& face : parsed.faces) {
        add_fan(face.vertices, mesh.triangles);
        if (!face.normals.empty()) add_fan(face.normals, mesh.normal_corners);
        if (!face.texture_coordinates.empty()) add_fan(face.texture_coordinates, mesh.texture_corners);
    }
}

void read_ply_into(MeshShape& mesh, std::string_view bytes) {
    PlyMesh parsed = parse_ply(bytes, kLargestNumber);
    mesh.positions = std::move(parsed.positions);
    mesh.normals = std::move(parsed.normals);
    mesh.texture_coordinates = std::move(parsed.texture_coordinates);
    mesh.triangles.reserve(parsed.corners.size() - 2 * parsed.face_count());  // n − 2 per n-gon
    for (std::size_t f = 0; f < parsed.face_count(); ++f) add_fan(parsed.face(f), mesh.triangles);
    if (!mesh.normals.empty()) mesh.normal_corners = mesh.triangles;
    if (!mesh.texture_coordinates.empty()) mesh.texture_corners = mesh.triangles;
}

// A mirroring transform turns every face's corners clockwise as seen from outside, so that the mesh would
// face (and emit) inward: the second and third corners of each triangle, and of its normals and texture
// coordinates, trade places, and each face turns counter-clockwise from outside again.
void keep_outside_after_mirroring(MeshShape& mesh) {
    for (auto* corners : {&mesh.triangles, &mesh.normal_corners, &mesh.texture_corners}) {
        for (auto& triangle : *corners) std::swap(triangle[1], triangle[2]);
    }
}

bool is_ply(const fs::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = char(std::tolower((unsigned char)c));
    return extension == ".ply";
}

// A mesh given in the scene itself: "positions", "triangles" of indices into them (from 0), and per vertex
// "normals" and "uv" when given (a pbrt scene's trianglemesh).
void read_inline_mesh(MeshShape& mesh, const Node& node) {
    const Node positions = node["positions"];
    for (std::size_t i = 0; i < positions.array_size(); ++i) mesh.positions.push_back(positions.element(i).vec3());
    const Node triangles = node["triangles"];
    const long long last = static_cast<long long>(mesh.positions.size()) - 1;
    for (std::size_t i = 0; i < triangles.array_size(); ++i) {
        const Node t = triangles.element(i);
        if (t.array_size() != 3) t.fail("must be 3 vertex indices, got " + std::to_string(t.array_size()));
        std::array<std::uint32_t, 3> corners{};
        for (std::size_t k = 0; k < 3; ++k) corners[k] = std::uint32_t(t.element(k).integer(0, last));
        mesh.triangles.push_back(corners);
    }
    auto per_vertex = [&](const char* key) {
        const Node values = node[key];
        if (values.array_size() != mesh.positions.size()) {
            values.fail("must have one entry per position (" + std::to_string(mesh.positions.size()) + "), got " +
                        std::to_string(values.array_size()));
        }
        return values;
    };
    if (node.has("normals")) {
        const Node normals = per_vertex("normals");
        for (std::size_t i = 0; i < normals.array_size(); ++i) mesh.normals.push_back(normals.element(i).direction());
        mesh.normal_corners = mesh.triangles;
    }
    if (node.has("uv")) {
        const Node uv = per_vertex("uv");
        for (std::size_t i = 0; i < uv.array_size(); ++i) {
            const Node pair = uv.element(i);
            if (pair.array_size() != 2) pair.fail("must be 2 numbers, got " + std::to_string(pair.array_size()));
            mesh.texture_coordinates.push_back({pair.element(0).real(), pair.element(1).real()});
        }
        mesh.texture_corners = mesh.triangles;
    }
}

// The triangles of a mesh file, read into `mesh`; a failure names the file.
void read_mesh_file(MeshShape& mesh, const Node& file, const fs::path& path) {
    const std::string shown_file = shown(path);
    const bool ply = is_ply(path);
    if (const std::string problem = not_a_regular_file(path); !problem.empty()) {
        file.fail(std::string("must name an OBJ or PLY file, got ") + shown_file + " (" + problem + ")");
    }
    // The text is read here; an OBJ's "mtllib" line cannot make the loader open another file.
    std::string text;
    try {
        text = read_whole_file(path);
    } catch (const InputError& e) {
        file.fail(shown_file + ": " + e.what());
    }
    try {
        if (ply) {
            read_ply_into(mesh, text);
        } else {
            read_obj_into(mesh, text);
        }
    } catch (const InputError& e) {
        file.fail(shown_file + ": " + e.what());
    }
}

// A mesh's triangles, given inline or read strictly from a file: OBJ, or PLY by its extension (.ply, any case). Polygons are split
// into fans (0, k, k + 1). A mesh whose every face has no area after its transform (repeated or collinear
// vertices, or coordinates so small that float's cross product underflows) is refused, as a lone triangle of
// no area is. Normals follow the transform's inverse transpose and are normalised; a mirroring transform
// keeps the mesh's outside (keep_outside_after_mirroring).
MeshShape read_mesh(const Node& node, const fs::path& scene_folder) {
    MeshShape mesh;
    if (node.has("transform")) mesh.transform = read_transform(node["transform"], true);
    const bool inline_data = !node.has("file");
    const Node file = inline_data ? node["positions"] : node["file"];
    std::string shown_file = "the mesh";
    if (inline_data) {
        read_inline_mesh(mesh, node);
    } else {
        mesh.file = file.string();
        shown_file = shown(scene_folder / mesh.file);
        read_mesh_file(mesh, file, scene_folder / mesh.file);
    }
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        mesh.positions[i] = mesh.transform.apply_to_point(mesh.positions[i]);
        if (node.has("transform")) {
            check_within_limits(node["transform"], "vertex " + std::to_string(i + 1), mesh.positions[i]);
        }
    }
    if (mesh.transform.mirrors()) keep_outside_after_mirroring(mesh);
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
        const Vec3 n = mesh.transform.apply_to_normal(mesh.normals[i]);
        if (!normalisable(n)) {
            file.fail(shown_file + ": normal " + std::to_string(i + 1) + " is too short to normalise" +
                      (node.has("transform") ? " after the transform" : ""));
        }
        mesh.normals[i] = glm::normalize(n);
    }
    std::size_t with_area = 0;
    for (const auto& [a, b, c] : mesh.triangles) {
        if (!zero_area(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]))
            ++with_area;
    }
    if (mesh.triangles.empty()) file.fail(shown_file + ": must have at least one face, got none");
    if (with_area == 0) {
        file.fail(shown_file + ": must have at least one face with an area, got " +
                  std::to_string(mesh.triangles.size()) +
                  " triangle(s), each with repeated or collinear vertices" +
                  (node.has("transform") ? " after the transform" : ""));
    }
    return mesh;
}

}  // namespace

Shape read_shape(const Node& node, const std::map<std::string, int>& material_index, const fs::path& scene_folder,
                 const std::vector<std::string_view>& material_names) {
    if (!node.json().is_object()) node.fail("must be an object, got " + std::string(node.json().type_name()));
    const std::string type = node["type"].string();
    Shape shape;
    shape.place = node.place();
    using Keys = std::vector<std::string_view>;
    auto keys = [](Keys k) {
        k.push_back("type");
        k.push_back("material");
        return k;
    };
    if (type == "sphere") {
        node.expect_object(keys({"center", "radius"}), "a sphere");
        shape.geometry = SphereShape{node["center"].vec3(), node["radius"].positive()};
    } else if (type == "quad") {
        node.expect_object(keys({"origin", "u", "v"}), "a quad");
        QuadShape q{node["origin"].vec3(), node["u"].vec3(), node["v"].vec3()};
        if (zero_area(q.u, q.v)) {
            node.fail("quad must have an area (u and v not parallel, not zero), got u = " + show(q.u) +
                      ", v = " + show(q.v));
        }
        shape.geometry = q;
    } else if (type == "triangle") {
        node.expect_object(keys({"vertices"}), "a triangle");
        const Node vertices = node["vertices"];
        if (vertices.array_size() != 3)
            vertices.fail("must be an array of 3 vertices, got " + std::to_string(vertices.array_size()));
        TriangleShape t{{vertices.element(0).vec3(), vertices.element(1).vec3(), vertices.element(2).vec3()}};
        if (zero_area(t.vertices[1] - t.vertices[0], t.vertices[2] - t.vertices[0])) {
            node.fail("triangle must have an area (vertices neither repeated nor collinear), got " +
                      show(t.vertices[0]) + ", " + show(t.vertices[1]) + ", " + show(t.vertices[2]));
        }
        shape.geometry = t;
    } else if (type == "plane") {
        node.expect_object(keys({"point", "normal"}), "a plane");
        shape.geometry = PlaneShape{node["point"].vec3(), node["normal"].direction()};
    } else if (type == "box") {
        node.expect_object(keys({"min", "max", "transform"}), "a box");
        BoxShape b{node["min"].vec3(), node["max"].vec3(), {}};
        for (int i = 0; i < 3; ++i) {
            if (!(b.max[i] > b.min[i])) {
                node["max"].fail("must exceed min on every axis, got min " + show(b.min) + ", max " +
                                 show(b.max));
            }
        }
        if (node.has("transform")) {
            b.transform = read_transform(node["transform"]);
            for (int corner = 0; corner < 8; ++corner) {
                const Vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                             (corner & 4) ? b.max.z : b.min.z);
                check_within_limits(node["transform"], "corner " + show(p), b.transform.apply_to_point(p));
            }
        }
        shape.geometry = b;
    } else if (type == "mesh") {
        node.expect_object(keys({"file", "transform", "positions", "triangles", "normals", "uv"}), "a mesh");
        if (node.has("file") == node.has("positions")) {
            node.fail("a mesh needs either \"file\" or \"positions\" and \"triangles\", not both");
        }
        if (node.has("file") && (node.has("normals") || node.has("uv") || node.has("triangles"))) {
            node["file"].fail("a mesh file gives its own triangles, normals and uv");
        }
        shape.geometry = read_mesh(node, scene_folder);
    } else {
        node["type"].fail("unknown shape type " + quote(type) + suggestion(type, kShapeTypes) +
                          "; expected sphere, quad, triangle, plane, box or mesh");
    }
    const Node material = node["material"];
    const std::string name = material.string();
    const auto found = material_index.find(name);
    if (found == material_index.end()) {
        material.fail("unknown material " + quote(name) + suggestion(name, material_names));
    }
    shape.material = found->second;
    return shape;
}

}  // namespace rt::scene_reading
