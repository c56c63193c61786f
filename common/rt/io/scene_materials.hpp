// Reading a scene file's materials (assets/scenes/README.md, "materials"): the type, whose MaterialKind reads
// its keys (material_kind.hpp), the colours or textures any type's colour parameters may be (an image read
// once, or a checker), and the medium inside or between the shapes.
#pragma once

#include <filesystem>
#include <string>

#include "rt/core/scene.hpp"
#include "rt/io/scene_node.hpp"

namespace rt::scene_reading {

// A participating medium (chapter 09): coefficients >= 0 per unit of length, |g| < 1.
MediumDesc read_medium(const Node& node);
// A colour parameter of m (&Material::albedo, ...): [r, g, b] in [0, limit], or a texture (added to
// m.textures), whose mean it holds then; returns it.
Color read_colour_parameter(const Node& node, const std::filesystem::path& scene_folder, Material& m,
                            Color Material::*parameter, double limit = 1);
// The material `name`, its keys read by its type's kind, and its emission; a texture's file is found relative
// to the scene's folder.
Material read_material(const Node& node, const std::string& name, const std::filesystem::path& scene_folder);

}  // namespace rt::scene_reading
