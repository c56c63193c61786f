// Reading a scene file (JSON, or pbrt-v4 through its translation; see assets/scenes/README.md). Every error is
// an InputError whose one line names the file and the place: "cornell.json: shapes[3].radius: must be > 0,
// got -1", "box.pbrt:12:5: Shape \"cone\": ...".
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "rt/core/scene.hpp"

namespace rt {

// The largest magnitude a number in a scene may have. Ray tests multiply up to three coordinates (a triple
// product), and (2·1e9)³·3 ≈ 2.4e28 stays far below float's 3.4e38; a scene beyond 1e9 units could not hold
// a unit-sized object in float anyway (the spacing of floats there is 64).
inline constexpr double kLargestSceneNumber = 1e9;

// A file whose name ends in .pbrt is a pbrt-v4 scene (pbrt_reader.hpp), read through its translation into
// the JSON format; any other file is JSON.
Scene load_scene(const std::filesystem::path& file);
// Parses scene text; `file` names it in messages and is where relative mesh paths start from.
Scene parse_scene(const std::string& text, const std::filesystem::path& file);
// Reads a scene already parsed as JSON (a pbrt scene's translation); `file` as for parse_scene.
Scene read_scene(const nlohmann::json& root, const std::filesystem::path& file);

}  // namespace rt
