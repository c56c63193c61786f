// Reading a scene file's materials (assets/scenes/README.md, "materials"): each type's keys and limits, colours
// or textures (an image read once, or a checker), a conductor's index or preset, and the medium inside or
// between the shapes.
#pragma once

#include <filesystem>
#include <string>

#include "rt/core/scene.hpp"
#include "rt/io/scene_node.hpp"

namespace rt::scene_reading {

// A participating medium (chapter 09): coefficients >= 0 per unit of length, |g| < 1.
MediumDesc read_medium(const Node& node);
// The material `name`; a texture's file is found relative to the scene's folder.
Material read_material(const Node& node, const std::string& name, const std::filesystem::path& scene_folder);

}  // namespace rt::scene_reading
