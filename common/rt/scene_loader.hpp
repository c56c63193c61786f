// Reading a scene file (JSON; see assets/scenes/README.md). Every error is an InputError whose one line names
// the file and the place: "cornell.json: shapes[3].radius: must be > 0, got -1".
#pragma once

#include <filesystem>
#include <string>

#include "rt/scene.hpp"

namespace rt {

Scene load_scene(const std::filesystem::path& file);
// Parses scene text; `file` names it in messages and is where relative mesh paths start from.
Scene parse_scene(const std::string& text, const std::filesystem::path& file);

}  // namespace rt
