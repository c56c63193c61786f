#include "rt/assets.hpp"

namespace rt {

std::filesystem::path assets_dir() { return RT_ASSETS_DIR; }
std::filesystem::path scene_path(const char* file_name) { return assets_dir() / "scenes" / file_name; }

}  // namespace rt
