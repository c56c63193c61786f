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

// FNV-1a of the scene file's bytes, then of what was loaded from every other file it read (Scene::inputs):
// each mesh's positions, triangles, normals and texture coordinates with their corners, the environment
// image's pixels, each image texture's size and texels. So an edited mesh, texture or environment image
// changes it too. Throws InputError when the scene file cannot be read.
std::uint64_t scene_fingerprint(const Scene& scene, const std::filesystem::path& scene_file);

// The options given on the command line other than `core` (the core flags, which a film records apart or
// which do not shape the image), in the order the chapter declares them: "--strategy=mis --max-depth=8".
std::string chapter_flags_text(const CLI::App& app, const std::set<std::string>& core);

}  // namespace rt
