// Reading a pbrt-v4 scene file: a strict reader of the subset of the format the course can render (the
// directives, parameter types, shapes, materials and lights that assets/scenes/README.md lists under "pbrt-v4
// scenes"), which translates the file into the course's own scene JSON. load_scene() then reads that JSON as
// it reads a .json file, so every chapter renders a pbrt scene unchanged; `rt_scene --to-json` prints it.
// Anything the course does not implement is refused with "FILE:LINE:COLUMN: " and what the course supports.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

struct PbrtTranslation {
    nlohmann::json scene;            // the course's scene format
    std::vector<std::string> notes;  // what the file says that changes nothing in the course's image
    std::vector<std::filesystem::path> included;  // the files it included, in the order read
};

// Reads `file` and the files it includes. Throws InputError with one located line.
PbrtTranslation translate_pbrt(const std::filesystem::path& file);
// The same for the text of `file` (the fuzzer's entry): its Include names are still read from its folder.
PbrtTranslation translate_pbrt_text(std::string_view text, const std::filesystem::path& file);

// Whether a scene file is a pbrt file: its name ends in .pbrt (any case).
bool is_pbrt_file(const std::filesystem::path& file);

}  // namespace rt
