// Reading a scene file's lights (assets/scenes/README.md, "lights"): point lights and the one environment light,
// a constant radiance or an image. Area lights are shapes whose material emits (scene_shapes.hpp).
#pragma once

#include <filesystem>

#include "rt/core/scene.hpp"
#include "rt/io/scene_node.hpp"

namespace rt::scene_reading {

// Adds the light at `node` to `scene`; an environment image is found relative to `scene_folder`.
void read_light(const Node& node, Scene& scene, const std::filesystem::path& scene_folder);

}  // namespace rt::scene_reading
