#include "rt/io/assets.hpp"

namespace rt {

std::filesystem::path assets_dir() { return RT_ASSETS_DIR; }
std::filesystem::path scene_path(const char* file_name) { return assets_dir() / "scenes" / file_name; }

std::filesystem::path resolve_scene(const std::string& given) {
    const std::filesystem::path path(given);
    std::error_code error;
    if (std::filesystem::exists(path, error) || path.has_parent_path() || given.empty()) return path;
    const std::filesystem::path course = scene_path(given.c_str());
    return std::filesystem::is_regular_file(course, error) ? course : path;
}

}  // namespace rt
