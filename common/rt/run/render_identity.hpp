// What a run's film records to be told apart from other renders' (FilmIdentity): a fingerprint of the scene
// and the chapter's own flags as given.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>

#include "rt/core/scene.hpp"

namespace rt {

// FNV-1a of the scene file's bytes, then of every mesh's vertices and triangles as loaded (so an edited OBJ
// file changes it too). Throws InputError when the file cannot be read.
std::uint64_t scene_fingerprint(const Scene& scene, const std::filesystem::path& scene_file);

// The options given on the command line other than `core` (the core flags, which a film records apart or
// which do not shape the image), in the order the chapter declares them: "--strategy=mis --max-depth=8".
std::string chapter_flags_text(const CLI::App& app, const std::set<std::string>& core);

}  // namespace rt
