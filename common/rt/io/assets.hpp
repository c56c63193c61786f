// Where the course's scenes and meshes are, so every executable finds its default scene from any folder.
#pragma once

#include <filesystem>
#include <string>

namespace rt {

std::filesystem::path assets_dir();
std::filesystem::path scene_path(const char* file_name);
// The scene a --scene value names: the path itself when it exists, else, for a bare file name, the course's
// assets/scenes/NAME when that exists (so `--scene ch06_mis.json` works from any folder), else the path as
// given (whose loading then says it is missing).
std::filesystem::path resolve_scene(const std::string& given);

}  // namespace rt
