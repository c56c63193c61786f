// Reading a scene file's shapes (assets/scenes/README.md, "shapes"): spheres, quads, triangles, planes, boxes
// with their transforms, and meshes read strictly from OBJ or PLY files; each names a material defined above it.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "rt/core/scene.hpp"
#include "rt/io/scene_node.hpp"

namespace rt::scene_reading {

// The shape at `node`; `material_index` maps the scene's material names to their indices, and a mesh file is
// found relative to `scene_folder`.
Shape read_shape(const Node& node, const std::map<std::string, int>& material_index,
                 const std::filesystem::path& scene_folder, const std::vector<std::string_view>& material_names);

}  // namespace rt::scene_reading
