// Files the user names (a scene, a mesh, a reference image): why a path is not a file that can be read, and
// reading one whole, with messages in words.
#pragma once

#include <filesystem>
#include <string>

namespace rt {

// Nothing when `path` is (or leads by links to) a regular file; otherwise what it is instead: "no such
// file", "a folder", "a path that cannot be followed (Too many levels of symbolic links)", ...
std::string not_a_regular_file(const std::filesystem::path& path);

// The file's bytes. Throws InputError "cannot be read (why)", or "too large to read into memory (N bytes)"
// when this machine or this process's limit (ulimit -v) cannot hold it.
std::string read_whole_file(const std::filesystem::path& path);

}  // namespace rt
