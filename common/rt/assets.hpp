// Where the course's scenes and meshes are, so every executable finds its default scene from any folder.
#pragma once

#include <filesystem>

namespace rt {

std::filesystem::path assets_dir();
std::filesystem::path scene_path(const char* file_name);

}  // namespace rt
